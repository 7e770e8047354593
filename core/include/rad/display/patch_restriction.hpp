#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace rad {

// How the patches a display is drawn on take their values from a solution on other patches of the same
// surfaces: display patch d's value is Σ share[k] · value[source[k]] for k in [begin[d], begin[d + 1]), the
// shares summing to 1. Empty: the display is drawn on the solution's own patches.
struct PatchRestriction {
    std::vector<std::uint32_t> begin;
    std::vector<std::uint32_t> source;
    std::vector<float> share;
    std::size_t source_count = 0;  // the solution's patches

    bool empty() const { return begin.empty(); }
    std::size_t size() const { return begin.empty() ? 0 : begin.size() - 1; }
    // Per display patch, from one value per solution patch. Throws std::invalid_argument for another count.
    std::vector<glm::dvec3> apply(std::span<const glm::dvec3> values) const;
};

}  // namespace rad
