#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// The pairs (a, b), a < b, of patches of the same surface that share a corner or an outline point (a corner
// of one lying on the other's edge, a T-vertex), each pair once.
std::vector<std::pair<std::uint32_t, std::uint32_t>> neighbour_pairs(const PatchMesh& mesh);

}  // namespace rad
