#include "rad/display/solution_display.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "display/display_patch_gather.hpp"
#include "display/display_patches.hpp"
#include "display/vertex_direct_light.hpp"
#include "display/vertex_final_gather.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/transport/transport_methods.hpp"

namespace rad {

std::vector<glm::dvec3> emitted_radiosity(const Scene& scene, const PatchMesh& patches) {
    std::vector<glm::dvec3> emitted(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q)
        emitted[q] = scene.surfaces[patches.patches[q].surface].material.emitted_radiosity();
    return emitted;
}

namespace {

// The size of the patches a solution is drawn on in smooth mode, 0 for its own elements: the uniform size
// for a method whose elements hold light linked to larger receivers, constant over them.
double display_patch_size(const SolutionSettings& settings) {
    const TransportMethod* method = find_transport_method(settings.subdivision);
    if (!method || !method->drawn_on_uniform_patches) return 0.0;
    return settings.patch_size / method->base_patch_scale;
}

// The arrays a display's light takes, on the patches it is drawn on.
struct DrawnPatches {
    const PatchMesh* mesh = nullptr;
    std::vector<double> area;
    std::vector<glm::dvec3> reflectance, emission, direct;
};

DrawnPatches solution_patches(const Solution& solution) {
    return {solution.elements.get(), solution.area, solution.reflectance, solution.emission, solution.direct};
}

// The solution's arrays carried to the display's patches: means of the elements under each; the exposed area
// is the display patch's area times its exposed share.
DrawnPatches restricted_patches(const DisplayPatches& display, const Solution& solution) {
    const PatchRestriction& r = display.from_solution;
    DrawnPatches out{&display.mesh,
                     {},
                     r.apply(solution.reflectance),
                     r.apply(solution.emission),
                     r.apply(solution.direct)};
    out.area.resize(display.mesh.size());
    for (std::size_t d = 0; d < out.area.size(); ++d)
        out.area[d] = display.exposed[d] * display.mesh.patches[d].area;
    return out;
}

std::vector<double> exposed_shares(const Solution& solution) {
    const PatchMesh& elements = *solution.elements;
    std::vector<double> exposed(elements.size());
    for (std::size_t q = 0; q < exposed.size(); ++q) {
        const double area = elements.patches[q].area;
        exposed[q] = area > 0.0 ? std::min(1.0, solution.area[q] / area) : 0.0;
    }
    return exposed;
}

// What the gathers subtract from the radiosity they meet: E where the vertices carry the emitters' direct
// light themselves (so it is not gathered twice), else nothing.
std::vector<glm::dvec3> gathered_source(const Scene& scene, const PatchMesh& patches,
                                        bool vertices_hold_direct) {
    if (!vertices_hold_direct) return std::vector<glm::dvec3>(patches.size(), glm::dvec3(0.0));
    return emitted_radiosity(scene, patches);
}

// A display of the solution's elements, or of patches of the display's own with the arrays carried over.
class DrawnSolution {
  public:
    DrawnSolution(const Scene& scene, const Solution& solution, bool smooth) : solution_(solution) {
        const double patch_size = display_patch_size(solution.settings);
        if (smooth && patch_size > 0.0) {
            solution_rays_.emplace(*solution.elements);
            own_.emplace(make_display_patches(scene, *solution.elements, *solution_rays_,
                                              exposed_shares(solution), patch_size));
        }
        drawn_ = own_ ? restricted_patches(*own_, solution) : solution_patches(solution);
    }

    const DrawnPatches& drawn() const { return drawn_; }
    bool has_own_patches() const { return own_.has_value(); }

    // The display patches' own gather of their last bounce from the solution's elements.
    void add_patch_gather(DisplayMesh& display, const Scene& scene, bool vertices_hold_direct,
                          const GatherTable* traced, Progress* progress) const {
        add_display_patch_gather(display,
                                 {.patches = &own_->mesh,
                                  .exposed = own_->exposed,
                                  .emission = drawn_.emission,
                                  .reflectance = drawn_.reflectance,
                                  .solution_rays = &*solution_rays_,
                                  .source = gathered_source(scene, *solution_.elements, vertices_hold_direct),
                                  .seed = solution_.settings.seed,
                                  .progress = progress,
                                  .traced = traced});
    }

    PatchRestriction take_restriction() { return own_ ? std::move(own_->from_solution) : PatchRestriction{}; }

  private:
    const Solution& solution_;
    std::optional<RayScene> solution_rays_;
    std::optional<DisplayPatches> own_;
    DrawnPatches drawn_;
};

// On the display's own patches each vertex keeps its exact value: the patches' means of the direct light
// are the elements', which a hierarchy links to larger elements (constant over them), and the patches' own
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
                      const RayScene& rays, bool vertices_hold_direct, bool near_surfaces_only,
                      std::uint64_t seed, Progress* progress) {
    add_vertex_final_gather(display, {.patches = drawn.mesh,
                                      .rays = &rays,
                                      .emission = drawn.emission,
                                      .reflectance = drawn.reflectance,
                                      .source = gathered_source(scene, *drawn.mesh, vertices_hold_direct),
                                      .seed = seed,
                                      .near_surfaces_only = near_surfaces_only,
                                      .progress = progress});
}

}  // namespace

DisplayMesh build_solution_display(const Scene& scene, const Solution& solution,
                                   const DisplayOptions& options, const GatherTable* traced_patch_gather,
                                   Progress* progress) {
    check_solution_fits(scene, solution);
    const bool smooth = options.mode == ColourMode::smooth;
    FinalGather gather = smooth ? options.final_gather : FinalGather::off;
    if (gather == FinalGather::automatic) gather = FinalGather::near;
    DrawnSolution solved(scene, solution, smooth);
    const DrawnPatches& drawn = solved.drawn();
    DisplayMesh display = build_display_mesh(*drawn.mesh, options, {&scene, drawn.reflectance});
    if (!smooth) return display;
    const bool direct = options.direct_light_at_vertices &&
                        draws_vertex_direct_light(*drawn.mesh, emitted_radiosity(scene, *drawn.mesh));
    if (!direct && gather == FinalGather::off) return display;
    const RayScene rays(*drawn.mesh);
    const std::uint64_t seed = solution.settings.seed;
    // The direct light first: it splits triangles along shadow edges, and the gathers then trace the
    // vertices it made and leave out the light it holds.
    if (direct) add_direct_light(display, scene, drawn, rays, seed, !solved.has_own_patches());
    const bool vertices_hold_direct = !display.direct.vertex.empty();
    if (gather != FinalGather::off) {
        if (solved.has_own_patches()) {
            solved.add_patch_gather(display, scene, vertices_hold_direct, traced_patch_gather, progress);
            // Without the patches' own gather (past its ray budget) their means are the elements', which hold
            // light linked to larger elements: every vertex gathers instead.
            if (display.patch_gather.empty() && options.final_gather == FinalGather::automatic)
                gather = FinalGather::on;
        }
        add_final_gather(display, scene, drawn, rays, vertices_hold_direct, gather == FinalGather::near, seed,
                         progress);
    }
    display.from_solution = solved.take_restriction();
    return display;
}

GatherTable display_patch_gather_table(const Scene& scene, const Solution& solution) {
    check_solution_fits(scene, solution);
    const DrawnSolution solved(scene, solution, true);
    if (!solved.has_own_patches()) return {};
    DisplayMesh rows;  // the table alone: no geometry
    rows.patch_count = solved.drawn().mesh->size();
    // The table alone is kept, not what its rows subtract.
    solved.add_patch_gather(rows, scene, false, nullptr, nullptr);
    return std::move(static_cast<GatherTable&>(rows.patch_gather));
}

DisplayMesh build_preview_display(const Scene& scene, const PatchMesh& patches, const DisplayOptions& options,
                                  std::span<const glm::dvec3> albedo, std::uint64_t seed) {
    DisplayMesh display = build_display_mesh(patches, options, {&scene, albedo});
    if (options.mode != ColourMode::smooth || !options.direct_light_at_vertices) return display;
    const std::vector<glm::dvec3> emitted = emitted_radiosity(scene, patches);
    if (!draws_vertex_direct_light(patches, emitted)) return display;
    const RayScene rays(patches);
    // No patch holds any of the light yet: each vertex keeps its own value.
    const std::vector<glm::dvec3> direct(patches.size(), glm::dvec3(0.0));
    std::vector<double> area(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q) area[q] = patches.patches[q].area;
    add_vertex_direct_light(display, {.patches = &patches,
                                      .rays = &rays,
                                      .emitted = emitted,
                                      .emission = emitted,
                                      .reflectance = albedo,
                                      .area = area,
                                      .patch_direct = direct,
                                      .seed = seed,
                                      .keep_patch_means = false});
    return display;
}

}  // namespace rad
