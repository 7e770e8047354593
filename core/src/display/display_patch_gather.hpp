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

// Most and fewest gather rays per display patch, and the rays of one display's patch gather at most. Below
// the fewest the display patches keep the mean of the leaves under them.
inline constexpr int kPatchGatherRays = 512;
inline constexpr int kPatchGatherMinRays = 64;
inline constexpr std::size_t kPatchGatherRayBudget = 8'000'000;

struct DisplayPatchGatherTraceInput {
    const PatchMesh* patches = nullptr;   // the display's own patches (DisplayPatches::mesh)
    std::span<const double> exposed{};    // per display patch, its uncovered share (DisplayPatches::exposed)
    const PatchMesh* solution = nullptr;  // the solution's patches
    const RayScene* solution_rays = nullptr;  // over the solution's patches
    std::uint64_t seed = 1;
    std::size_t ray_budget = kPatchGatherRayBudget;
    Progress* progress = nullptr;  // advanced per display patch; its cancel throws Cancelled
    // A table these rays made before (a saved solution's), taken instead of tracing when it has a row per
    // display patch and its patches are the solution's; null: trace.
    const GatherTable* traced = nullptr;
};

// Fills display.traced.patch_gather: the last bounce of each display patch, gathered from the solution's
// patches by cosine-weighted rays from points spread over it (the hemisphere estimator's rays). Each solution
// patch a ray meets from the front counts its share of the rays, divided by the display patch's exposed
// share (rays from its covered part meet the back of what covers it), so a patch shows the light of its
// exposed part, as a uniform patch does. A hierarchy's leaves hold light linked to larger elements; gathered
// once over them, the display's patches show the light that varies across those elements. Leaves it empty
// where the budget leaves fewer than kPatchGatherMinRays per patch. Clears display.light.patch_gather.
// Throws std::invalid_argument when `exposed` does not have one entry per patch.
void trace_display_patch_gather(DisplayMesh& display, const DisplayPatchGatherTraceInput& input);

// What the rows are evaluated with: per display patch, what its radiosity starts from (E, plus ρ H_out under
// a sky or sun) and its reflectance; per solution patch, what the vertices' direct light already holds of
// its radiosity (its E where the display traces the emitters' light at the vertices, else 0).
struct DisplayPatchGatherArrays {
    std::span<const glm::dvec3> emission{};
    std::span<const glm::dvec3> reflectance{};
    std::span<const glm::dvec3> source{};
};

// Fills display.light.patch_gather where rows are traced; traces nothing. Throws std::invalid_argument when
// the arrays do not have one entry per patch.
void light_display_patch_gather(DisplayMesh& display, const DisplayPatchGatherArrays& arrays);

}  // namespace rad
