#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "mesh/patch_boundary.hpp"
#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// How each patch's radiosity gradient along its plane follows from its neighbours':
// ∇B_p = Σ_q c_q (B_q − B_p) over the patches q that share a boundary point with p (a corner, or a
// T-vertex on either's edge) on the same surface and bend from it by less than the crease angle (the
// least-squares plane through their centroids). No terms where the neighbours cannot fix a plane (fewer
// than two, or all in a line). Compressed rows: patch p's terms are [begin[p], begin[p + 1]).
struct PatchGradients {
    std::vector<std::uint32_t> begin;
    std::vector<std::uint32_t> neighbour;
    std::vector<glm::dvec3> coefficient;  // c_q, a vector in the patch's plane
};

// `at`: patches_at_points(mesh).
PatchGradients patch_gradients(const PatchMesh& mesh, const PointPatches& at, double cos_crease);

}  // namespace rad
