#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// glTF holds triangles only, where a modeller (or an OBJ) had quads; the mesher cuts a quad into a grid of
// quad patches but each triangle into a finer grid of triangles. So two triangles that share an edge
// (running opposite ways) and together make a planar (within 1e-7 of their size; build_scene keeps polygons
// planar within 1e-6 whole) convex quad become that quad again, its corners in the order of the triangle fan
// that split it. `corners` holds corner triples into `positions`; the rest stay triangles, in their order.
std::vector<std::vector<std::uint32_t>> merge_triangle_pairs(const std::vector<std::uint32_t>& corners,
                                                             const std::vector<glm::dvec3>& positions);

}  // namespace rad
