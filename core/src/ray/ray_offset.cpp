#include "ray/ray_offset.hpp"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace rad {

double ray_offset(const PatchMesh& patches) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : patches.points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    if (patches.points.empty()) return 0.0;
    const glm::dvec3 magnitude = glm::max(glm::abs(lo), glm::abs(hi));
    const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    return std::max(kRayOffsetFraction * glm::length(hi - lo),
                    kRayOffsetUlps * std::numeric_limits<float>::epsilon() * largest);
}

}  // namespace rad
