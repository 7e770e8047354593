#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "rad/display/gather_table.hpp"
#include "rad/display/patch_restriction.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/texture.hpp"

namespace rad {

// smooth: each vertex takes the area-weighted radiosity of the patches around it that lie on the same
//         surface (hence material) and bend from one another by less than the crease angle, so walls do not
//         bleed into each other and a box's edges stay sharp while a tessellated curve shades smoothly.
//         Where a smaller patch's corner lies inside a larger one's edge (a T-vertex, listed in the mesh's
//         outlines), the larger patch takes part in that vertex too and is drawn as a fan from its centroid
//         (which shows its own value) through every point of its outline, so no crack opens there.
// flat:   every patch has its own corners and shows its own radiosity (outlines are not needed).
// In both, where a corner of one surface lies inside another's edge (surfaces share no corners), the other's
// triangle is drawn as a fan through that point too, with the colour its edge had there: no crack pixels
// along seams.
enum class ColourMode { smooth, flat };

// How smooth mode sets a vertex from the patches around it.
// average: their area-weighted mean. A vertex on a surface's border then takes the value half a patch
//          inside, which brightens concave edges and blurs shadow edges.
// linear:  each patch's value extrapolated to the vertex along the patch's least-squares gradient (from
//          its neighbours on the same smooth surface), then area-weighted; exact for a linear field at
//          every vertex, borders included. A vertex keeps within the range of the patches it is made from,
//          widened by that range: where a patch's neighbours lie nearly in a line its gradient is huge, and
//          unlimited it would show bright and dark artifacts. Negative results are shown as 0.
enum class Reconstruction { average, linear };

// automatic: near. A hierarchy's leaves hold the light of links made for a larger receiver; its display is
//            drawn on patches of its own, which gather their last bounce first (DisplayPatches,
//            trace_display_patch_gather), and every vertex gathers where they cannot.
// near: only vertices beside another surface (VertexFinalGatherInput::near_surfaces_only), any transport.
// on: every vertex. off: none.
enum class FinalGather { automatic, near, on, off };

struct DisplayOptions {
    ColourMode mode = ColourMode::smooth;
    // Patches meeting at a corner share a vertex when their normals differ by less than this. 30° keeps the
    // faces of boxes apart (90°) and joins the facets of a curved surface tessellated finer than 12 sides
    // per circle.
    double crease_angle_degrees = 30.0;
    Reconstruction reconstruction = Reconstruction::linear;
    // Smooth mode: whoever builds the display over a solved transport adds the emitters' direct light at
    // each vertex (add_vertex_direct_light, which traces rays; build_display_mesh does not).
    bool direct_light_at_vertices = true;
    // Smooth mode: whether whoever builds the display over a solved transport gathers the last bounce at
    // each vertex (add_vertex_final_gather).
    FinalGather final_gather = FinalGather::automatic;
};

// What texel detail needs: the scene the patches were cut from (its textured surfaces) and the reflectance
// each patch has in the transport (Transport::reflectance, in the patches' order: a textured patch's mean
// albedo). Without a scene every surface shows its radiosity alone.
struct DisplayTexturing {
    const Scene* scene = nullptr;
    std::span<const glm::dvec3> reflectance;
};

// What rays found on a display's geometry, whatever the light of the solution drawn on it: the same
// elements and emitters drawn with another solution (other reflectances, another sky) need no ray
// (relight_display).
struct DisplayTraces {
    // The emitters' direct irradiance H_d at each vertex, as traced (add_vertex_direct_light), the emitted
    // radiosity E per display patch it was traced for, and per vertex 1 where it sees none of the emitters
    // (its value is kept as traced); all empty where the display does not trace the emitters' light.
    std::vector<glm::dvec3> direct_irradiance;
    std::vector<glm::dvec3> direct_emitted;
    std::vector<std::uint8_t> direct_umbra;
    // Per vertex, the share of its rays that met each display patch's front (add_vertex_final_gather).
    GatherTable gather;
    // Per display patch of its own, the share of its rays that met each solution patch's front
    // (trace_display_patch_gather).
    GatherTable patch_gather;
};

// The light of one solution on a display (besides its radiosity, which vertex_radiance takes): what each
// layer of DisplayTraces is evaluated with. Replaced whole when another solution of the same elements is
// drawn (relight_display); the geometry and the traces stay.
struct DisplayLight {
    // How vertex_radiance turns a textured patch's radiosity into irradiance: (B − emission) ·
    // inverse_albedo.
    struct PatchIrradiance {
        glm::dvec3 emission{0.0};
        glm::dvec3 inverse_albedo{0.0};  // 1 / ρ per channel, 0 where ρ is 0
    };
    std::vector<PatchIrradiance> patch_irradiance;  // per patch where any is textured, else empty
    // The emitters' direct light at the vertices, or all empty. A vertex shows its patches' reconstruction
    // of B − s · patch, plus s · vertex, s being how much of the direct light the radiosity holds
    // (direct_light_share).
    struct Direct {
        std::vector<glm::dvec3> patch;     // per patch ρ H_d: the direct light its radiosity holds
        std::vector<glm::dvec3> emission;  // per patch E, and
        std::vector<double> area;          // its area, for direct_light_share
        std::vector<glm::vec3> vertex;     // per vertex ρ H_d at the vertex (H_d on textured surfaces)
    };
    Direct direct;
    // The vertices' final gather (DisplayTraces::gather), or all empty. A vertex with a row shows the
    // patches' reconstruction of `emission` alone, plus its direct light, plus its reflectance times
    // Σ weight · (B − source) over its row's patches: the last bounce resolved at the vertex, not the patch.
    // Vertices without a row (textured ones) show the reconstruction as before.
    struct Gather {
        std::vector<glm::dvec3> reflectance;  // per vertex
        std::vector<glm::dvec3> emission;     // per patch, what the patch's radiosity starts from
        std::vector<glm::dvec3> source;       // per patch, what the vertices' direct light already holds
    };
    Gather gather;
    // The display's own patches' gather (DisplayTraces::patch_gather), or all empty. A display patch then
    // shows emission + s · direct.patch + reflectance · Σ weight · (B − source) over the solution's patches
    // its rays met (s as for the vertices), in place of the mean of the solution's patches under it.
    struct PatchGather {
        std::vector<glm::dvec3> emission;     // per display patch
        std::vector<glm::dvec3> reflectance;  // per display patch
        std::vector<glm::dvec3> source;       // per solution patch
    };
    PatchGather patch_gather;
};

// The geometry to draw, built once: a renderer uploads positions, normals and triangles once and, after
// each solver step, only the colours vertex_radiance returns (one per vertex, in the same order). Beside it,
// what rays found on it (traced) and the light of the solution it draws (light), each replaced on its own.
//
// Textured surfaces keep their texel detail: their vertices carry H / π, the irradiance the patches around
// them receive (from B = E + ρ H with each patch's own mean albedo ρ), and a pixel shows
// emitted_radiance + albedo_scale · texel · H / π, the texel's albedo times the interpolated irradiance.
// Other vertices carry the radiance B / π itself.
struct DisplayMesh {
    // A run of triangles of one textured surface, drawn with its texture.
    struct TexturedRange {
        std::uint32_t first_triangle = 0;
        std::uint32_t triangle_count = 0;
        std::shared_ptr<const Texture> texture;
        glm::vec3 albedo_scale{1.0f};  // a texel's linear colour times this is its albedo
        glm::vec3 emitted_radiance{0.0f};
    };

    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;             // unit, front side
    std::vector<glm::uvec3> triangles;          // counter-clockwise from the front
    std::vector<std::uint32_t> triangle_patch;  // the patch each triangle belongs to (for picking)
    // Vertex v's colour is Σ weight[k] B[weight_patch[k]] / π over k in [weight_begin[v], weight_begin[v+1]),
    // at least 0; its weights sum to 1.
    std::vector<std::uint32_t> weight_begin{0};
    std::vector<std::uint32_t> weight_patch;
    std::vector<float> weight;
    std::size_t patch_count = 0;               // the patches the display is drawn on
    std::vector<std::uint32_t> patch_surface;  // per patch, its surface
    // Where the display is drawn on patches of its own (DisplayPatches), how they take the solution's
    // radiosity: vertex_radiance and direct_light_share take one entry per solution patch and apply it
    // first, and each patch's exposed area (its area times its uncovered share). Empty: the display's
    // patches are the solution's.
    PatchRestriction from_solution;
    std::vector<double> own_patch_area;
    // Per vertex where any surface is textured (else empty); (0, 0) outside the textured ranges.
    std::vector<glm::vec2> texcoords;
    std::vector<TexturedRange> textured;       // in triangle order, not overlapping
    std::vector<std::uint8_t> patch_textured;  // per patch where any is textured, else empty

    DisplayTraces traced;
    DisplayLight light;

    std::size_t vertex_count() const { return positions.size(); }
    // How many entries the radiosity given to vertex_radiance has.
    std::size_t solution_patch_count() const {
        return from_solution.empty() ? patch_count : from_solution.source_count;
    }
    // Whether patch q's vertices carry irradiance under a texture.
    bool textured_patch(std::uint32_t q) const { return !patch_textured.empty() && patch_textured[q] != 0; }
};

// Throws std::invalid_argument for a crease angle outside [0°, 180°] or a reflectance of another size.
DisplayMesh build_display_mesh(const PatchMesh& patches, const DisplayOptions& options = {},
                               const DisplayTexturing& texturing = {});

// How much of the emitters' direct light a radiosity holds, from 0 (the emission alone) to 1 (every
// solution past its first bounce): Σ A (B − E) / Σ A ρ H_d over the patches, in luminance, at most 1. 0
// where the mesh has no direct light of its own (DisplayMesh::direct empty).
double direct_light_share(const DisplayMesh& display, std::span<const glm::dvec3> radiosity);

// Radiance L = B / π per display vertex (H / π on textured surfaces), from the radiosity B per patch of the
// solution (a Solver's display_solution(); where the display has patches of its own, from_solution and
// patch_gather carry it to them first). `direct_share` is what direct_light_share measures unless given: a
// view of one bounce alone gives 1 for the first and 0 for the others. Writes radiance[v] for every vertex;
// radiance must hold vertex_count() entries. `final_gather` false shows the patches' reconstruction even
// where the vertices have a gather (a view of one bounce's light, which is no solution to gather from).
void vertex_radiance(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                     std::span<glm::vec3> radiance, std::optional<double> direct_share = {},
                     bool final_gather = true);
std::vector<glm::vec3> vertex_radiance(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                                       std::optional<double> direct_share = {}, bool final_gather = true);

// vertex_radiance of a solution being stepped bounce by bounce: the vertices with a gather row gather
// `previous` (the radiosity one Jacobi step earlier) instead. A gather reflects what it gathers once more, so
// over the latest step those vertices would show one bounce more than their neighbours that keep the
// patches' reconstruction (a halo beside the walls while the light builds up); over the step before, every
// vertex shows the bounces of its step. Converged, previous and radiosity are the same.
std::vector<glm::vec3> stepped_vertex_radiance(const DisplayMesh& display,
                                               std::span<const glm::dvec3> radiosity,
                                               std::span<const glm::dvec3> previous);

// The radiance each vertex itself shows, from what vertex_radiance gave: a textured vertex's value times the
// albedo at its texture coordinates, plus the surface's emitted radiance; other vertices as they are. What
// one colour per vertex can hold (a PLY export), without the texels between vertices.
std::vector<glm::vec3> vertex_shown_radiance(const DisplayMesh& display, std::span<const glm::vec3> radiance);

}  // namespace rad
