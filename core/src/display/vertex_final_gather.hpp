#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>

#include "rad/display/display_mesh.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// Most and fewest gather rays per display vertex; below the fewest the vertices keep the patches'
// reconstruction (their noise would show).
inline constexpr int kFinalGatherRays = 256;
inline constexpr int kFinalGatherMinRays = 128;
// The rays of one display's gather at most, so a mesh of many vertices takes fewer rays each.
inline constexpr std::size_t kFinalGatherRayBudget = 32'000'000;
// A gather near surfaces only (near_surfaces_only): the rays of a vertex that gathers, and the fewest worth
// tracing (fewer are noisier than the patches' means they replace); the probe rays that look for a surface
// within kNearPatchSizes of the vertex's patch size, on a face at least kNearFacePatchSizes of it across.
inline constexpr int kNearGatherRays = 1024;
inline constexpr int kNearGatherMinRays = 512;
inline constexpr int kNearProbeRays = 64;
inline constexpr double kNearPatchSizes = 2.0;
inline constexpr double kNearFacePatchSizes = 1.0;

struct VertexFinalGatherTraceInput {
    const PatchMesh* patches = nullptr;  // the patches the display mesh was built from
    const RayScene* rays = nullptr;      // over the same patches
    std::uint64_t seed = 1;
    std::size_t ray_budget = kFinalGatherRayBudget;
    // Where patches hold their own light (uniform patches), their means are right and their reconstruction
    // is smooth; only beside another surface (a corner, a block's foot) does the light vary across a patch
    // faster than it shows. Then only vertices whose probe rays meet a surface within kNearPatchSizes of
    // their largest patch's size gather, with kNearGatherRays rays; the others keep the reconstruction. The
    // surface met must be on an input face at least kNearFacePatchSizes of that size across (√area): the
    // light beside faces smaller than the vertices' spacing (a row of small lamps) varies faster than
    // samples at the vertices can show, and point samples there alias into bands the patches' means do not
    // have.
    bool near_surfaces_only = false;
    Progress* progress = nullptr;  // advanced per vertex; its cancel throws Cancelled
};

// Fills display.traced.gather: a final gather's rows (the last bounce taken at each vertex instead of each
// patch). From each untextured vertex, cosine-weighted rays over a stratified square; each front a ray meets
// counts its share of the rays, so a vertex's irradiance is Σ share · B of the patches met. Where a patch's
// radiosity is right but its light varies across it (a corner, the floor beside a block), the vertex shows
// the variation the patch's mean hides; the solution's own error arrives there once reflected. Leaves it
// empty where the budget leaves fewer than kFinalGatherMinRays per vertex (kNearGatherMinRays near surfaces
// only). Call it after the direct light (which splits triangles). Clears display.light.gather.
void trace_vertex_final_gather(DisplayMesh& display, const VertexFinalGatherTraceInput& input);

// What the rows are evaluated with, per patch: what its radiosity starts from in the transport (E, plus
// ρ H_out under a sky or sun), its reflectance, and what the vertices' direct light already holds of its
// radiosity (its E where the display traces the emitters' light at the vertices, else 0).
struct VertexFinalGatherArrays {
    std::span<const glm::dvec3> emission{};
    std::span<const glm::dvec3> reflectance{};
    std::span<const glm::dvec3> source{};
};

// Fills display.light.gather where rows are traced (each vertex's reflectance from its patches'); traces
// nothing. Throws std::invalid_argument when the arrays do not have one entry per patch.
void light_vertex_final_gather(DisplayMesh& display, const VertexFinalGatherArrays& arrays);

// trace_vertex_final_gather, then light_vertex_final_gather.
struct VertexFinalGatherInput {
    const PatchMesh* patches = nullptr;
    const RayScene* rays = nullptr;
    std::span<const glm::dvec3> emission{};
    std::span<const glm::dvec3> reflectance{};
    std::span<const glm::dvec3> source{};
    std::uint64_t seed = 1;
    std::size_t ray_budget = kFinalGatherRayBudget;
    bool near_surfaces_only = false;
    Progress* progress = nullptr;
};
void add_vertex_final_gather(DisplayMesh& display, const VertexFinalGatherInput& input);

}  // namespace rad
