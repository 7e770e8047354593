#include "pipeline/solution_display.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "rad/display/display_patch_gather.hpp"
#include "rad/display/display_patches.hpp"
#include "rad/display/vertex_direct_light.hpp"
#include "rad/display/vertex_final_gather.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {

std::vector<glm::dvec3> emitted_radiosity(const Scene& scene, const PatchMesh& patches) {
    std::vector<glm::dvec3> emitted(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q)
        emitted[q] = scene.surfaces[patches.patches[q].surface].material.emitted_radiosity();
    return emitted;
}

namespace {

// The arrays a display's light takes, on the patches it is drawn on.
struct DrawnPatches {
    const PatchMesh* mesh = nullptr;
    std::vector<double> area;
    std::vector<glm::dvec3> reflectance, emission, direct;
};

DrawnPatches solution_patches(const SolvedPatches& solved) {
    return {solved.mesh,
            {solved.area.begin(), solved.area.end()},
            {solved.reflectance.begin(), solved.reflectance.end()},
            {solved.emission.begin(), solved.emission.end()},
            {solved.direct.begin(), solved.direct.end()}};
}

// The solution's arrays carried to the display's patches: means of the leaves under each; the exposed area
// is the display patch's area times its exposed share.
DrawnPatches restricted_patches(const DisplayPatches& display, const SolvedPatches& solved) {
    const PatchRestriction& r = display.from_solution;
    DrawnPatches out{
        &display.mesh, {}, r.apply(solved.reflectance), r.apply(solved.emission), r.apply(solved.direct)};
    out.area.resize(display.mesh.size());
    for (std::size_t d = 0; d < out.area.size(); ++d)
        out.area[d] = display.exposed[d] * display.mesh.patches[d].area;
    return out;
}

// On the display's own patches each vertex keeps its exact value: the patches' means of the direct light
// are the leaves', which a hierarchy links to larger elements (constant over them), and the patches' own
// gather holds the rest of their light.
void add_direct_light(DisplayMesh& display, const Scene& scene, const DrawnPatches& drawn,
                      const RayScene& rays, std::uint64_t seed, bool keep_patch_means) {
    const std::vector<glm::dvec3> emitted = emitted_radiosity(scene, *drawn.mesh);
    add_vertex_direct_light(display, {.patches = drawn.mesh,
                                      .rays = &rays,
                                      .emitted = emitted,
                                      .emission = drawn.emission,
                                      .reflectance = drawn.reflectance,
                                      .area = drawn.area,
                                      .patch_direct = drawn.direct,
                                      .seed = seed,
                                      .keep_patch_means = keep_patch_means});
}

void add_final_gather(DisplayMesh& display, const Scene& scene, const DrawnPatches& drawn,
                      const RayScene& rays, bool near_surfaces_only, std::uint64_t seed, Progress* progress) {
    // What the vertices' own direct light holds is not gathered again.
    std::vector<glm::dvec3> source(drawn.mesh->size(), glm::dvec3(0.0));
    if (!display.direct.vertex.empty()) source = emitted_radiosity(scene, *drawn.mesh);
    add_vertex_final_gather(display, {.patches = drawn.mesh,
                                      .rays = &rays,
                                      .emission = drawn.emission,
                                      .reflectance = drawn.reflectance,
                                      .source = source,
                                      .seed = seed,
                                      .near_surfaces_only = near_surfaces_only,
                                      .progress = progress});
}

void add_patch_gather(DisplayMesh& display, const Scene& scene, const DisplayPatches& own,
                      const DrawnPatches& drawn, const SolvedPatches& solved, const RayScene& solution_rays,
                      std::uint64_t seed, Progress* progress) {
    std::vector<glm::dvec3> source(solved.mesh->size(), glm::dvec3(0.0));
    if (!display.direct.vertex.empty()) source = emitted_radiosity(scene, *solved.mesh);
    add_display_patch_gather(display, {.patches = &own.mesh,
                                       .exposed = own.exposed,
                                       .emission = drawn.emission,
                                       .reflectance = drawn.reflectance,
                                       .solution_rays = &solution_rays,
                                       .source = source,
                                       .seed = seed,
                                       .progress = progress,
                                       .traced = solved.patch_gather});
}

std::vector<double> exposed_shares(const SolvedPatches& solved) {
    std::vector<double> exposed(solved.mesh->size());
    for (std::size_t q = 0; q < exposed.size(); ++q) {
        const double area = solved.mesh->patches[q].area;
        exposed[q] = area > 0.0 ? std::min(1.0, solved.area[q] / area) : 0.0;
    }
    return exposed;
}

}  // namespace

DisplayMesh build_solution_display(const Scene& scene, const SolvedPatches& solved,
                                   const SolutionDisplaySettings& settings, Progress* progress) {
    const DisplayOptions& options = settings.options;
    const bool smooth = options.mode == ColourMode::smooth;
    FinalGather gather = smooth ? options.final_gather : FinalGather::off;
    if (gather == FinalGather::automatic) gather = FinalGather::near;
    std::optional<RayScene> solution_rays;
    std::optional<DisplayPatches> own;
    if (smooth && settings.display_patch_size > 0.0) {
        solution_rays.emplace(*solved.mesh);
        own.emplace(make_display_patches(scene, *solved.mesh, *solution_rays, exposed_shares(solved),
                                         settings.display_patch_size));
    }
    const DrawnPatches drawn = own ? restricted_patches(*own, solved) : solution_patches(solved);
    DisplayMesh display = build_display_mesh(*drawn.mesh, options, {&scene, drawn.reflectance});
    if (!smooth) return display;
    const bool direct = options.direct_light_at_vertices &&
                        draws_vertex_direct_light(*drawn.mesh, emitted_radiosity(scene, *drawn.mesh));
    if (!direct && gather == FinalGather::off) return display;
    const RayScene rays(*drawn.mesh);
    if (direct) add_direct_light(display, scene, drawn, rays, settings.seed, !own);
    if (gather != FinalGather::off) {
        if (own) {
            add_patch_gather(display, scene, *own, drawn, solved, *solution_rays, settings.seed, progress);
            // Without the patches' own gather (past its ray budget) their means are the leaves', which hold
            // light linked to larger elements: every vertex gathers instead.
            if (display.patch_gather.empty() && options.final_gather == FinalGather::automatic)
                gather = FinalGather::on;
        }
        add_final_gather(display, scene, drawn, rays, gather == FinalGather::near, settings.seed, progress);
    }
    if (own) display.from_solution = std::move(own->from_solution);
    return display;
}

GatherTable display_patch_gather_table(const Scene& scene, const SolvedPatches& solved,
                                       const SolutionDisplaySettings& settings) {
    if (settings.display_patch_size <= 0.0) return {};
    const RayScene solution_rays(*solved.mesh);
    const DisplayPatches own = make_display_patches(scene, *solved.mesh, solution_rays,
                                                    exposed_shares(solved), settings.display_patch_size);
    const DrawnPatches drawn = restricted_patches(own, solved);
    DisplayMesh rows;  // the table alone: no geometry
    rows.patch_count = own.mesh.size();
    add_patch_gather(rows, scene, own, drawn, solved, solution_rays, settings.seed, nullptr);
    return std::move(static_cast<GatherTable&>(rows.patch_gather));
}

}  // namespace rad
