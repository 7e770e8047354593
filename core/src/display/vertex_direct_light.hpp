#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {

// Shadow rays per display vertex for its direct light, drawn over the emitter patches by power.
inline constexpr int kVertexShadowRays = 128;
// A vertex that sees all of the light takes the exact sum of every emitter patch's unoccluded factor where
// vertices × emitter patches stay within this many factors; beyond, the draws' estimate, whose spread where
// the patches' factors differ much from their weights (beside a luminous ceiling) streaks the walls.
inline constexpr double kVertexExactFactorBudget = 2e7;

// What the emitters' direct light at the vertices is traced with.
struct VertexDirectTraceInput {
    const PatchMesh* patches = nullptr;  // the patches the display mesh was built from
    const RayScene* rays = nullptr;      // over the same geometry
    // Per patch, in the patches' order, the radiosity it emits itself: E = π Le (the light sources).
    std::span<const glm::dvec3> emitted{};
    std::uint64_t seed = 1;
    // Split the display's triangles where the direct light steps across them (a shadow's edge), so the step
    // is drawn finer than the patches.
    bool split_shadow_edges = true;
};

// What the traced direct light is evaluated with: per patch, in the patches' order, what its radiosity
// starts from in the transport (E, plus ρ H_out under a sky or sun), its reflectance and its exposed area as
// the transport has them, and ρ H_d, the part of its radiosity that is the emitters' light reflected once
// (ρ times the transport's gather of E).
struct VertexDirectLightArrays {
    std::span<const glm::dvec3> emission{};
    std::span<const glm::dvec3> reflectance{};
    std::span<const double> area{};
    std::span<const glm::dvec3> patch_direct{};
    // false before any transport exists (a preview of the light while form factors run): patch_direct is
    // not known, and each vertex keeps its exact value.
    bool keep_patch_means = true;
};

// Fills display.traced's direct light: H_d at every vertex, where a patch's mean would blur shadow edges and
// the light's falloff over its area. At each vertex (moved a thousandth of the way towards its patches'
// centroid, so a vertex on an edge is not in the plane of the surface beyond) the exact unoccluded
// point-to-polygon factor of each emitter patch drawn times the share of its shadow rays that nothing blocks;
// up to kVertexShadowRays rays drawn over the emitters by power (each drawn when they are few), so every
// vertex's value is unbiased; 16 first, and the rest only where they disagree (a penumbra). Where the 16
// all reach the light, the exact unoccluded sum over every emitter patch instead (within
// kVertexExactFactorBudget). With split_shadow_edges, the triangles are then split along the edges where
// that light steps and the new vertices traced too, so `display` should be one build_display_mesh made
// (a second call splits it further). Leaves it empty where no patch emits, or where the emitters are so many
// or cover so much of the scene that the transport leaves their light to hemisphere rays (a furnace): light
// from sources that large is smooth. Clears display.light.direct. Throws std::invalid_argument when
// `emitted` does not have one entry per patch.
void trace_vertex_direct_light(DisplayMesh& display, const VertexDirectTraceInput& input);

// Fills display.light.direct from the traced H_d (nothing where none is traced): ρ H_d per vertex (H_d on
// textured surfaces), each vertex that sees some of the light then moved by its patches' shortfalls (what
// their triangles draw against ρ H_d, what they hold), so a falloff's chords do not darken or brighten them;
// vertices in umbra keep 0. vertex_radiance shows each vertex its patches' reconstruction of the rest of the
// light plus this. Traces nothing. Throws std::invalid_argument when the arrays do not have one entry per
// patch.
void light_vertex_direct_light(DisplayMesh& display, const VertexDirectLightArrays& arrays);

// trace_vertex_direct_light, then light_vertex_direct_light.
struct VertexDirectLightInput {
    const PatchMesh* patches = nullptr;
    const RayScene* rays = nullptr;
    std::span<const glm::dvec3> emitted{};
    std::span<const glm::dvec3> emission{};
    std::span<const glm::dvec3> reflectance{};
    std::span<const double> area{};
    std::span<const glm::dvec3> patch_direct{};
    std::uint64_t seed = 1;
    bool keep_patch_means = true;
    bool split_shadow_edges = true;
};
void add_vertex_direct_light(DisplayMesh& display, const VertexDirectLightInput& input);

// Whether add_vertex_direct_light would trace anything for patches emitting `emitted` (E per patch), so a
// caller can skip building the rays for a scene it leaves to the patches (a furnace). Throws
// std::invalid_argument when `emitted` does not have one entry per patch.
bool draws_vertex_direct_light(const PatchMesh& patches, std::span<const glm::dvec3> emitted);

// H_d, the emitters' direct irradiance, at points with unit normals as add_vertex_direct_light estimates it
// at each vertex (before the patches' means are kept; the points are where rays leave, off their surface by
// the ray offset); 0 everywhere where it leaves the light to the patches. `emitted` is E per patch. Throws
// std::invalid_argument when the sizes do not match.
std::vector<glm::dvec3> direct_irradiance_at(const PatchMesh& patches, const RayScene& rays,
                                             std::span<const glm::dvec3> emitted,
                                             std::span<const glm::dvec3> points,
                                             std::span<const glm::dvec3> normals, std::uint64_t seed = 1,
                                             double exact_factor_budget = kVertexExactFactorBudget);

}  // namespace rad
