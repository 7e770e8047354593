#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

namespace rad {

inline constexpr std::uint32_t kNoSolid = std::numeric_limits<std::uint32_t>::max();

// The closed solids among polygons: sets of polygons of one group (an OBJ group or object of one name, a
// glTF mesh)
// joined along their edges (corners compared by exact position, so a file that writes each face's corners
// anew still closes) in which every edge is used exactly
// twice, once in each direction, and whose signed volume is positive (faces outwards: a room modelled from
// inside closes too, but with its faces inwards it is a hollow, not a solid).
struct Solids {
    std::vector<std::uint32_t> of_polygon;             // per polygon, its solid or kNoSolid
    std::vector<std::vector<std::uint32_t>> polygons;  // per solid, its polygons
};

// `polygons` holds each polygon's distinct corners in order (empty for one without area), `groups` its group.
// Solids of different groups are told apart even where they share edges and faces (slabs overlapping at a
// corner); within a group, where more than two faces meet at an edge, each face closes with its neighbour
// around the edge whose wedge lies behind both.
Solids find_solids(const std::vector<std::vector<glm::dvec3>>& polygons,
                   const std::vector<std::uint32_t>& groups);

}  // namespace rad
