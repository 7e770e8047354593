#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "light/point_direct_light.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {

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
// up to kDirectShadowRays rays drawn over the emitters by power (each drawn when they are few), so every
// vertex's value is unbiased; 16 first, and the rest only where they disagree (a penumbra). Where the 16
// all reach the light, the exact unoccluded sum over every emitter patch instead (within
// kExactFactorBudget). With split_shadow_edges, the triangles are then split along the edges where
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

}  // namespace rad
