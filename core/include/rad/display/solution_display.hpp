#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/display/gather_table.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solution.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// Per patch, what it emits itself (E = π Le of its surface's material): the scene's light sources.
std::vector<glm::dvec3> emitted_radiosity(const Scene& scene, const PatchMesh& patches);

// The display of a solution of `scene`, from any source (a solve or a saved file): first its geometry and
// what rays find on it (DisplayTraces), then the solution's light on it (relight_display). The mesh, then in
// this order the emitters' direct light at its vertices (smooth mode, where there are emitters to trace; it
// splits triangles along shadow edges), the display patches' own gather and the vertices' final gather,
// each tracing what the stages before it made. A solution whose method draws it on patches of the uniform
// size (TransportMethod::drawn_on_uniform_patches: a hierarchy's leaves hold light linked to larger
// receivers) is drawn on patches of its own, each gathering its last bounce from the solution's elements;
// where the ray budget leaves that out, every vertex gathers instead. FinalGather::automatic is `near`: only
// the vertices beside another surface gather. `traced_patch_gather`, when given, is that patch gather as
// traced before (a saved file's), used instead of tracing it again. `element_rays`, when given, is a ray
// scene over the solution's elements, shared with whoever else traces them (built here otherwise). Throws
// std::invalid_argument when the solution does not fit the scene (check_solution_fits) and Cancelled when
// `progress` is cancelled.
DisplayMesh build_solution_display(const Scene& scene, const Solution& solution,
                                   const DisplayOptions& options,
                                   const GatherTable* traced_patch_gather = nullptr,
                                   Progress* progress = nullptr, const RayScene* element_rays = nullptr);

// Whether `display`'s geometry and traces hold for `solution` of `scene`: a solution on the same elements
// whose emitters emit as they did when the display was traced (other reflectances, another sky or sun, more
// bounces all keep them).
bool display_traces_fit(const DisplayMesh& display, const Scene& scene, const Solution& solution);

// Replaces only the display's light (DisplayLight) with `solution`'s, from the traces it holds: no ray, and
// the same values a new build_solution_display of that solution would give. Throws std::invalid_argument
// when the solution does not fit the scene or the display's traces (display_traces_fit).
void relight_display(DisplayMesh& display, const Scene& scene, const Solution& solution);

// The display patches' own gather alone (its table: rows, patches and weights), for a saved file to keep;
// empty where the solution is drawn on its own elements or the ray budget leaves the gather out.
GatherTable display_patch_gather_table(const Scene& scene, const Solution& solution);

// The display of `patches` before any solution exists (a preview while the transport is built): the mesh
// with texel detail from `albedo` (per patch), and in smooth mode the emitters' direct light at its
// vertices, each vertex keeping its own value (no patch holds any of that light yet). Shown over the
// emission (emitted_radiosity) with direct_share 1.
DisplayMesh build_preview_display(const Scene& scene, const PatchMesh& patches, const DisplayOptions& options,
                                  std::span<const glm::dvec3> albedo, std::uint64_t seed);

}  // namespace rad
