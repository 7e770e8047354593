#pragma once

#include <glm/mat4x4.hpp>
#include <vector>

#include "scene/gltf/gltf_file.hpp"

namespace rad {

// A node of the scene shown, with its transform from its own frame to the world's.
struct PlacedNode {
    int node = -1;
    glm::dmat4 world{1.0};
};

// The nodes of the default scene (or else scene 0, or all root nodes when the file has no scenes), each once,
// parents before children. Refuses (InputError) a node index out of range, a node with two parents, a
// hierarchy with a cycle, and a transform that is malformed or not finite. Runs without recursion, so a deep
// hierarchy cannot overflow the stack.
std::vector<PlacedNode> place_nodes(const GltfFile& file);

}  // namespace rad
