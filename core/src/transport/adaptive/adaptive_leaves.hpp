#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>

#include "rad/mesh/element_tree.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "util/luminance.hpp"

namespace rad {

// The leaves of one adaptive pass with their solution: what the split criteria read.
struct SolvedLeaves {
    const ElementTree& tree;
    std::span<const std::uint32_t> elements;  // leaf k is element elements[k] of the tree
    const PatchMesh& mesh;                    // leaf k is patch k
    const UniformTransport& system;
    std::span<const glm::dvec3> radiosity;

    // The share of leaf i that other geometry does not cover (the system keeps only that part's area).
    double exposed_share(std::size_t i) const { return system.area[i] / mesh.patches[i].area; }
    std::uint32_t base_patch(std::size_t i) const { return tree[elements[i]].base_patch; }
};

// Leaves whose exposed share is below this are under other geometry (a floor under a box): their radiosity
// is of a sliver nobody sees, so the gradient criterion does not compare them.
inline constexpr double kMinExposedShare = 0.05;

}  // namespace rad
