#pragma once

#include <array>
#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace rad {

// Newell's normal of a polygon: its direction is the polygon's front normal for counter-clockwise vertices
// and its length is twice the area; robust for non-planar and concave polygons.
glm::dvec3 newell_normal(std::span<const glm::dvec3> polygon);

double polygon_area(std::span<const glm::dvec3> polygon);

// Planar within `relative_tolerance` of the polygon's size, and strictly convex with a consistent winding.
bool is_planar_convex(std::span<const glm::dvec3> polygon, double relative_tolerance = 1e-6);

// Triangles (indices into `polygon`, same winding) covering a simple polygon, concave or slightly
// non-planar: a quad is split along its shorter diagonal, anything else by ear clipping in its plane.
std::vector<std::array<std::size_t, 3>> triangulate_polygon(std::span<const glm::dvec3> polygon);

}  // namespace rad
