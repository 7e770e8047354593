// Emitter sampling and points on patches for the path tracer.
#include <algorithm>
#include <array>
#include <glm/geometric.hpp>

#include "reference/path_tracer_paths.hpp"
#include "util/luminance.hpp"

namespace rad::path_tracing {

glm::dvec3 point_on_patch(const PatchMesh& patches, std::uint32_t patch, glm::dvec2 u) {
    const glm::uvec4& c = patches.corners[patch];
    if (patches.is_triangle(patch)) {
        return point_on_triangle(patches.points[c[0]], patches.points[c[1]], patches.points[c[2]], u);
    }
    const std::array<glm::dvec3, 4> quad{patches.points[c[0]], patches.points[c[1]], patches.points[c[2]],
                                         patches.points[c[3]]};
    return point_on_convex_polygon(quad, u);
}

glm::dvec3 onto_patch_plane(const PatchMesh& patches, std::uint32_t patch, const glm::dvec3& p) {
    const Patch& q = patches.patches[patch];
    return p - glm::dot(p - q.centroid, q.normal) * q.normal;
}

EmitterSampler::EmitterSampler(const PatchMesh& patches, std::span<const glm::dvec3> emitted_radiance)
    : patches_(&patches) {
    double total = 0.0;
    for (std::uint32_t i = 0; i < patches.size(); ++i) {
        const double power = patches.patches[i].area * luminance(emitted_radiance[i]);
        if (!(power > 0.0)) continue;
        patch_.push_back(i);
        total += power;
        cdf_.push_back(total);
    }
    pdf_area_.assign(patches.size(), 0.0);
    for (std::size_t k = 0; k < patch_.size(); ++k) {
        const double before = k == 0 ? 0.0 : cdf_[k - 1];
        pdf_area_[patch_[k]] = (cdf_[k] - before) / total / patches.patches[patch_[k]].area;
    }
    for (double& c : cdf_) c /= total;
    if (!cdf_.empty()) cdf_.back() = 1.0;
}

EmitterSampler::Sample EmitterSampler::sample(RandomStream& random) const {
    const double pick = random.uniform();
    const auto k = static_cast<std::size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), pick) - cdf_.begin());
    const std::size_t index = std::min(k, patch_.size() - 1);
    const glm::dvec2 u(random.uniform(), random.uniform());
    return {point_on_patch(*patches_, patch_[index], u), patch_[index], pdf_area_[patch_[index]]};
}

}  // namespace rad::path_tracing
