#include "rad/display/solution_display.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "display/display_patch_gather.hpp"
#include "display/display_patches.hpp"
#include "display/patch_texturing.hpp"
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

std::vector<double> exposed_shares(const Solution& solution) {
    const PatchMesh& elements = *solution.elements;
    std::vector<double> exposed(elements.size());
    for (std::size_t q = 0; q < exposed.size(); ++q) {
        const double area = elements.patches[q].area;
        exposed[q] = area > 0.0 ? std::min(1.0, solution.area[q] / area) : 0.0;
    }
    return exposed;
}

// Per display patch, what it emits itself.
std::vector<glm::dvec3> emitted_on_display(const Scene& scene, const DisplayMesh& display) {
    std::vector<glm::dvec3> emitted(display.patch_count);
    for (std::size_t q = 0; q < emitted.size(); ++q)
        emitted[q] = scene.surfaces.at(display.patch_surface[q]).material.emitted_radiosity();
    return emitted;
}

// What the gathers subtract from the radiosity they meet: E where the vertices carry the emitters' direct
// light themselves (so it is not gathered twice), else nothing.
std::vector<glm::dvec3> gathered_source(std::vector<glm::dvec3> emitted, bool vertices_hold_direct) {
    if (!vertices_hold_direct) std::fill(emitted.begin(), emitted.end(), glm::dvec3(0.0));
    return emitted;
}

// The solution's arrays on the patches the display is drawn on: its own, or the means of the elements under
// each display patch, whose exposed area is the display patch's area times its exposed share.
struct DrawnArrays {
    std::vector<double> area;
    std::vector<glm::dvec3> reflectance, emission, direct;
};

DrawnArrays drawn_arrays(const DisplayMesh& display, const Solution& solution) {
    const PatchRestriction& r = display.from_solution;
    if (r.empty()) return {solution.area, solution.reflectance, solution.emission, solution.direct};
    return {display.own_patch_area, r.apply(solution.reflectance), r.apply(solution.emission),
            r.apply(solution.direct)};
}

// A ray scene over the solution's elements: the one given, or one built the first time it is asked for.
class ElementRays {
  public:
    ElementRays(const PatchMesh& elements, const RayScene* given) : elements_(elements), given_(given) {}
    const RayScene& get() {
        if (given_) return *given_;
        if (!built_) built_.emplace(elements_);
        return *built_;
    }

  private:
    const PatchMesh& elements_;
    const RayScene* given_;
    std::optional<RayScene> built_;
};

std::optional<DisplayPatches> own_patches(const Scene& scene, const Solution& solution, ElementRays& rays) {
    const double patch_size = display_patch_size(solution.settings);
    if (!(patch_size > 0.0)) return std::nullopt;
    return make_display_patches(scene, *solution.elements, rays.get(), exposed_shares(solution), patch_size);
}

void trace_patch_gather(DisplayMesh& display, const Solution& solution, const DisplayPatches& own,
                        ElementRays& rays, const GatherTable* traced, Progress* progress) {
    trace_display_patch_gather(display, {.patches = &own.mesh,
                                         .exposed = own.exposed,
                                         .solution = solution.elements.get(),
                                         .solution_rays = &rays.get(),
                                         .seed = solution.settings.seed,
                                         .progress = progress,
                                         .traced = traced});
}

// What rays find on the drawn patches: the emitters' direct light at the vertices (which splits triangles
// along shadow edges), then the gathers, which trace the vertices it made.
void trace_display(DisplayMesh& display, const Scene& scene, const Solution& solution,
                   const DisplayOptions& options, const PatchMesh& drawn, const DisplayPatches* own,
                   ElementRays& element_rays, const GatherTable* traced_patch_gather, Progress* progress) {
    FinalGather gather =
        options.final_gather == FinalGather::automatic ? FinalGather::near : options.final_gather;
    const std::uint64_t seed = solution.settings.seed;
    const std::vector<glm::dvec3> emitted = emitted_on_display(scene, display);
    // Kept wherever the display would trace the emitters, so an edit that makes a surface emit is seen.
    if (options.direct_light_at_vertices) display.traced.direct_emitted = emitted;
    const bool direct = options.direct_light_at_vertices && draws_vertex_direct_light(drawn, emitted);
    if (!direct && gather == FinalGather::off) return;
    std::optional<RayScene> own_rays;
    if (own) own_rays.emplace(drawn);
    const RayScene& rays = own ? *own_rays : element_rays.get();
    if (direct)
        trace_vertex_direct_light(display,
                                  {.patches = &drawn, .rays = &rays, .emitted = emitted, .seed = seed});
    if (gather == FinalGather::off) return;
    if (own) {
        trace_patch_gather(display, solution, *own, element_rays, traced_patch_gather, progress);
        // Without the patches' own gather (past its ray budget) their means are the elements', which hold
        // light linked to larger elements: every vertex gathers instead.
        if (display.traced.patch_gather.empty() && options.final_gather == FinalGather::automatic)
            gather = FinalGather::on;
    }
    trace_vertex_final_gather(display, {.patches = &drawn,
                                        .rays = &rays,
                                        .seed = seed,
                                        .near_surfaces_only = gather == FinalGather::near,
                                        .progress = progress});
}

// relight_display once the solution is known to fit the scene and the display's traces.
void light_display(DisplayMesh& display, const Scene& scene, const Solution& solution) {
    const DrawnArrays drawn = drawn_arrays(display, solution);
    light_textured_patches(display, scene, drawn.reflectance);
    // On the display's own patches each vertex keeps its exact value: the patches' means of the direct light
    // are the elements', which a hierarchy links to larger elements (constant over them), and the patches'
    // own gather holds the rest of their light.
    light_vertex_direct_light(display, {.emission = drawn.emission,
                                        .reflectance = drawn.reflectance,
                                        .area = drawn.area,
                                        .patch_direct = drawn.direct,
                                        .keep_patch_means = display.from_solution.empty()});
    const bool vertices_hold_direct = !display.light.direct.vertex.empty();
    if (!display.from_solution.empty()) {
        light_display_patch_gather(
            display,
            {.emission = drawn.emission,
             .reflectance = drawn.reflectance,
             .source = gathered_source(emitted_radiosity(scene, *solution.elements), vertices_hold_direct)});
    }
    light_vertex_final_gather(
        display, {.emission = drawn.emission,
                  .reflectance = drawn.reflectance,
                  .source = gathered_source(emitted_on_display(scene, display), vertices_hold_direct)});
}

}  // namespace

DisplayMesh build_solution_display(const Scene& scene, const Solution& solution,
                                   const DisplayOptions& options, const GatherTable* traced_patch_gather,
                                   Progress* progress, const RayScene* element_rays) {
    check_solution_fits(scene, solution);
    const bool smooth = options.mode == ColourMode::smooth;
    ElementRays rays(*solution.elements, element_rays);
    std::optional<DisplayPatches> own = smooth ? own_patches(scene, solution, rays) : std::nullopt;
    const PatchMesh& drawn = own ? own->mesh : *solution.elements;
    const std::vector<glm::dvec3> drawn_reflectance =
        own ? own->from_solution.apply(solution.reflectance) : solution.reflectance;
    DisplayMesh display = build_display_mesh(drawn, options, {&scene, drawn_reflectance});
    if (own) {
        display.from_solution = std::move(own->from_solution);
        display.own_patch_area.resize(drawn.size());
        for (std::size_t d = 0; d < drawn.size(); ++d)
            display.own_patch_area[d] = own->exposed[d] * drawn.patches[d].area;
    }
    if (smooth)
        trace_display(display, scene, solution, options, drawn, own ? &*own : nullptr, rays,
                      traced_patch_gather, progress);
    light_display(display, scene, solution);
    return display;
}

bool display_traces_fit(const DisplayMesh& display, const Scene& scene, const Solution& solution) {
    if (display.solution_patch_count() != solution.elements->size()) return false;
    if (display.traced.direct_emitted.empty()) return true;
    return display.traced.direct_emitted == emitted_on_display(scene, display);
}

void relight_display(DisplayMesh& display, const Scene& scene, const Solution& solution) {
    check_solution_fits(scene, solution);
    if (!display_traces_fit(display, scene, solution))
        throw std::invalid_argument("relight_display: the display was traced for other elements or emitters");
    light_display(display, scene, solution);
}

GatherTable display_patch_gather_table(const Scene& scene, const Solution& solution) {
    check_solution_fits(scene, solution);
    ElementRays rays(*solution.elements, nullptr);
    const std::optional<DisplayPatches> own = own_patches(scene, solution, rays);
    if (!own) return {};
    DisplayMesh rows;  // the table alone: no geometry
    rows.patch_count = own->mesh.size();
    trace_patch_gather(rows, solution, *own, rays, nullptr, nullptr);
    return std::move(rows.traced.patch_gather);
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
