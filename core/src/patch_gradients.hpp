#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "rad/patches.hpp"

namespace rad {

// How a patch's radiosity gradient along its plane follows from its neighbours': ∇B_p = Σ_q c_q (B_q − B_p)
// over the patches q that share a corner with p on the same surface and bend from it by less than the
// crease angle (the least-squares plane through their centroids). Empty where the neighbours cannot fix a
// plane (fewer than two, or all in a line).
struct PatchGradient {
    std::vector<std::uint32_t> neighbour;
    std::vector<glm::dvec3> coefficient;  // c_q, a vector in the patch's plane
};

std::vector<PatchGradient> patch_gradients(const PatchMesh& mesh, double cos_crease);

}  // namespace rad
