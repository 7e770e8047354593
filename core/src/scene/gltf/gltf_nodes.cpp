#include "scene/gltf/gltf_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "rad/util/error.hpp"

namespace rad {

namespace {

[[noreturn]] void refuse(const GltfFile& file, const std::string& what) {
    throw InputError(gltf_message(file, what));
}

std::string node_name(int node) {
    return "nodes[" + std::to_string(node) + "]";
}

void check_node_index(const GltfFile& file, int node, const std::string& where) {
    const std::size_t count = file.model.nodes.size();
    if (node < 0 || static_cast<std::size_t>(node) >= count)
        refuse(file, where + ": node " + std::to_string(node) + " does not exist (" + std::to_string(count) +
                         " in the file)");
}

// glTF lets a node have one parent at most; without that rule a small file could instance a subtree
// exponentially often.
std::vector<int> parents(const GltfFile& file) {
    const auto& nodes = file.model.nodes;
    std::vector<int> parent(nodes.size(), -1);
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        for (int child : nodes[n].children) {
            check_node_index(file, child, node_name(static_cast<int>(n)));
            int& p = parent[static_cast<std::size_t>(child)];
            if (p >= 0)
                refuse(file, node_name(child) + ": is a child of both " + node_name(p) + " and " +
                                 node_name(static_cast<int>(n)));
            p = static_cast<int>(n);
        }
    }
    return parent;
}

std::vector<int> root_nodes(const GltfFile& file, const std::vector<int>& parent) {
    const tinygltf::Model& model = file.model;
    if (model.scenes.empty()) {
        std::vector<int> roots;
        for (std::size_t n = 0; n < parent.size(); ++n)
            if (parent[n] < 0) roots.push_back(static_cast<int>(n));
        return roots;
    }
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(scene) >= model.scenes.size())
        refuse(file, "scene " + std::to_string(scene) + " does not exist (" +
                         std::to_string(model.scenes.size()) + " in the file)");
    const std::string where = "scenes[" + std::to_string(scene) + "]";
    for (int node : model.scenes[static_cast<std::size_t>(scene)].nodes) check_node_index(file, node, where);
    return model.scenes[static_cast<std::size_t>(scene)].nodes;
}

void check_values(const GltfFile& file, int node, const std::vector<double>& values, std::size_t size,
                  const char* what) {
    if (values.empty()) return;
    if (values.size() != size)
        refuse(file, node_name(node) + ": " + what + " has " + std::to_string(values.size()) +
                         " numbers, not " + std::to_string(size));
    for (double v : values)
        if (!std::isfinite(v)) refuse(file, node_name(node) + ": " + what + " is not finite");
}

glm::dmat4 local_transform(const GltfFile& file, int index) {
    const tinygltf::Node& node = file.model.nodes[static_cast<std::size_t>(index)];
    check_values(file, index, node.matrix, 16, "matrix");
    check_values(file, index, node.translation, 3, "translation");
    check_values(file, index, node.rotation, 4, "rotation");
    check_values(file, index, node.scale, 3, "scale");
    if (!node.matrix.empty()) return glm::make_mat4(node.matrix.data());  // column-major, as glTF's
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (!node.rotation.empty()) {
        const auto& r = node.rotation;  // x, y, z, w
        const glm::dquat q(r[3], r[0], r[1], r[2]);
        const double length = glm::length(q);
        if (!(length > 0.0))
            refuse(file, node_name(index) + ": rotation is not a rotation (zero quaternion)");
        m *= glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

std::vector<PlacedNode> place_nodes(const GltfFile& file) {
    const std::vector<int> parent = parents(file);
    std::vector<bool> placed(parent.size(), false);
    std::vector<PlacedNode> out;
    std::vector<PlacedNode> stack;
    for (int root : root_nodes(file, parent)) stack.push_back({root, glm::dmat4(1.0)});
    // The roots in their order, each subtree depth first.
    std::reverse(stack.begin(), stack.end());
    while (!stack.empty()) {
        PlacedNode current = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::size_t>(current.node);
        if (placed[index])
            refuse(file, node_name(current.node) +
                             ": reached twice through the node hierarchy (a cycle, or a node listed twice)");
        placed[index] = true;
        current.world = current.world * local_transform(file, current.node);
        if (!finite(current.world))
            refuse(file, node_name(current.node) + ": its transform from the world is not finite");
        out.push_back(current);
        const auto& children = file.model.nodes[static_cast<std::size_t>(current.node)].children;
        for (auto child = children.rbegin(); child != children.rend(); ++child)
            stack.push_back({*child, current.world});
    }
    return out;
}

}  // namespace rad
