#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "viewer/solver_snapshot.hpp"

namespace rad {

// The scene's materials by name, in the order of their first surface: the table the panel shows and edits
// (an edit changes every surface of that name at once).
std::shared_ptr<const std::vector<ViewerMaterial>> scene_materials(const Scene& scene);

// Per display triangle, its material's place in `materials` (scene_materials' table), for picking by a
// click.
std::vector<std::uint32_t> triangle_materials(const Scene& scene,
                                              const std::vector<ViewerMaterial>& materials,
                                              const DisplayMesh& display);

}  // namespace rad
