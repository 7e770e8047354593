#pragma once

#include <optional>
#include <vector>

#include "rad/scene/scene.hpp"
#include "scene/gltf/gltf_file.hpp"
#include "scene/gltf/gltf_nodes.hpp"

namespace rad {

// The first perspective camera among the placed nodes, in their order: the eye at the node's origin, looking
// down its −Z with its +Y up, the field of view its yfov. Orthographic cameras are left out, counted in a
// warning. Refuses (InputError) a camera index out of range and a yfov outside (0, 180°).
std::optional<Camera> first_camera(GltfFile& file, const std::vector<PlacedNode>& nodes);

}  // namespace rad
