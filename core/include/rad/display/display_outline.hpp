#pragma once

#include <cstdint>
#include <vector>

#include "rad/display/display_mesh.hpp"

namespace rad {

// The patches' edges as pairs of display-vertex indices, for drawing as lines: every edge of a patch's
// triangles that no other triangle of the same patch shares (so a quad's diagonal is left out).
std::vector<std::uint32_t> patch_outline(const DisplayMesh& display);

}  // namespace rad
