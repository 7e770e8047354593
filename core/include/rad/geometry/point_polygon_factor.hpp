#pragma once

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>
#include <span>

namespace rad {

// Patches have 3 or 4 corners; clipping one by a plane adds at most one more. Room for a second clip.
inline constexpr std::size_t kMaxPolygonCorners = 8;

// A small convex polygon held by value, so the inner loops of the analytic estimator never allocate.
struct ConvexPolygon {
    std::array<glm::dvec3, kMaxPolygonCorners> corners{};
    std::size_t count = 0;

    std::span<const glm::dvec3> span() const { return {corners.data(), count}; }
    bool empty() const { return count < 3; }
};

ConvexPolygon make_convex_polygon(std::span<const glm::dvec3> corners);

// The part of `polygon` on the side of the plane through `point` that `normal` points to (Sutherland-Hodgman
// against one plane); empty when nothing of it lies there. The corners keep their order.
ConvexPolygon clip_to_front(const ConvexPolygon& polygon, const glm::dvec3& point, const glm::dvec3& normal);

// The form factor from a differential area at x with unit normal n to a convex polygon (Lambert's formula,
// after Nishita and Nakamae): positive when x sees the polygon's front (corners counter-clockwise from the
// front), negative when it sees its back. The polygon must lie wholly in front of x's tangent plane; clip it
// with clip_to_front first when it may not.
double point_polygon_factor(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon);

}  // namespace rad
