#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// Per patch, what it emits itself (E = π Le of its surface's material): the scene's light sources.
std::vector<glm::dvec3> emitted_radiosity(const Scene& scene, const PatchMesh& patches);

// A solution's patches with what its display takes of each, per patch: the exposed area, the reflectance,
// what its radiosity starts from (E, plus ρ H_out under a sky or sun) and ρ H_d, the emitters' light
// reflected once.
struct SolvedPatches {
    const PatchMesh* mesh = nullptr;
    std::span<const double> area{};
    std::span<const glm::dvec3> reflectance{};
    std::span<const glm::dvec3> emission{};
    std::span<const glm::dvec3> direct{};
    // The display patches' own gather as traced before (a saved solution's), or null: traced here.
    const GatherTable* patch_gather = nullptr;
};

struct SolutionDisplaySettings {
    DisplayOptions options;
    // Smooth mode draws on patches of this size (DisplayPatches) instead of the solution's own; 0: on its
    // own. A hierarchy's leaves take light linked to larger receivers, constant over them, and are drawn so;
    // uniform and adaptive patches hold their own light.
    double display_patch_size = 0.0;
    std::uint64_t seed = 1;
};

// The display of a solved scene: the mesh, the emitters' direct light at its vertices (smooth mode, where
// there are emitters to trace) and the final gather. FinalGather::automatic is `near`: only the vertices
// beside another surface gather, where the light varies faster than the patches show; on patches of the
// display's own, each patch first gathers its last bounce from the solution's (add_display_patch_gather),
// and where the ray budget leaves that out, every vertex gathers instead. Throws Cancelled when `progress`
// is cancelled.
DisplayMesh build_solution_display(const Scene& scene, const SolvedPatches& solved,
                                   const SolutionDisplaySettings& settings, Progress* progress = nullptr);

// The display patches' own gather alone (its table: rows, patches and weights), for a saved solution to keep;
// empty where the settings draw on the solution's own patches or the ray budget leaves the gather out.
GatherTable display_patch_gather_table(const Scene& scene, const SolvedPatches& solved,
                                       const SolutionDisplaySettings& settings);

}  // namespace rad
