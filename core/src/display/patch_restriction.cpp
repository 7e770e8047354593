#include "rad/display/patch_restriction.hpp"

#include <stdexcept>

namespace rad {

std::vector<glm::dvec3> PatchRestriction::apply(std::span<const glm::dvec3> values) const {
    if (values.size() != source_count)
        throw std::invalid_argument("PatchRestriction: the values do not have one entry per solution patch");
    std::vector<glm::dvec3> out(size(), glm::dvec3(0.0));
    for (std::size_t d = 0; d < out.size(); ++d)
        for (std::uint32_t k = begin[d]; k < begin[d + 1]; ++k)
            out[d] += static_cast<double>(share[k]) * values[source[k]];
    return out;
}

}  // namespace rad
