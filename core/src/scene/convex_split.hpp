#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// A convex polygon split by the plane normal · x = offset: the part in front (normal · x ≥ offset) and the
// part behind, either empty where the polygon lies wholly on one side (corners within `tolerance` of the
// plane count as on it). The corners keep their order, so each part keeps the polygon's winding; corners of
// the polygon are copied exactly.
struct ConvexSplit {
    std::vector<glm::dvec3> front, back;
};
ConvexSplit split_convex(const std::vector<glm::dvec3>& polygon, const glm::dvec3& normal, double offset,
                         double tolerance);

}  // namespace rad
