// Adaptive subdivision: the leaves keep the scene's area, splits gather at contact edges and shadow
// boundaries and not where radiosity is even, the bounds hold, and the result is about as accurate as a
// uniform mesh with more patches, measured against a path-traced reference at points.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "expect_input_error.hpp"
#include "point_reference.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/adaptive/adaptive_subdivision.hpp"
#include "rad/util/error.hpp"
#include "transport/adaptive/adaptive_gradient.hpp"
#include "transport/adaptive/adaptive_shadow.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"
#include "transport/uniform/form_factors_memory.hpp"

namespace rad {
namespace {

double extent_of(const Scene& scene) {
    return bounding_box(scene).largest_extent();
}

double total_area(const PatchMesh& mesh) {
    double sum = 0.0;
    for (const Patch& p : mesh.patches) sum += p.area;
    return sum;
}

std::uint32_t surface_named(const Scene& scene, const std::string& name) {
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s)
        if (scene.surfaces[s].name == name) return s;
    throw std::runtime_error("no surface " + name);
}

struct Solution {
    PatchMesh mesh;
    std::vector<glm::dvec3> radiosity;
    double seconds = 0.0;
};

// The form-factor options the program uses: the default ones, with the scene's emitters.
FormFactorOptions program_options(const Scene& scene, FormFactorOptions ff) {
    ff.emitting_surfaces = emitting_surfaces(scene);
    return ff;
}

Solution solve_uniform(const Scene& scene, double patch_size, const FormFactorOptions& ff = {}) {
    const auto start = std::chrono::steady_clock::now();
    Solution out{build_patches(scene, MeshingOptions{patch_size}), {}, 0.0};
    const UniformTransport system =
        make_uniform_transport(scene, out.mesh, compute_form_factors(out.mesh, program_options(scene, ff)));
    const auto solver = make_solver(SolverMethod::conjugate_gradient, system, SolverOptions{});
    while (!solver->report().finished()) solver->step();
    out.radiosity.assign(solver->solution().begin(), solver->solution().end());
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

AdaptiveResult adapt(const Scene& scene, double base_size, const AdaptiveOptions& options,
                     const FormFactorOptions& ff = {}) {
    return subdivide_adaptively(scene, build_patches(scene, MeshingOptions{base_size}),
                                program_options(scene, ff), SolverMethod::conjugate_gradient, SolverOptions{},
                                options);
}

void print_passes(const AdaptiveReport& report) {
    for (std::size_t k = 0; k < report.passes.size(); ++k) {
        const AdaptivePass& p = report.passes[k];
        std::printf(
            "  pass %zu: %5zu patches, form factors %.2f s, solve %.2f s, criteria %.2f s; asked: gradient "
            "%zu, "
            "shadow %zu, too small %zu; split %zu\n",
            k + 1, p.patches, p.form_factor_seconds, p.solve_seconds, p.criteria_seconds, p.gradient_leaves,
            p.shadow_leaves, p.too_small, p.split);
    }
    std::printf("  stopped: %s, %.2f s in all\n", std::string(adaptive_stop_name(report.stop)).c_str(),
                report.seconds);
}

// builtin:cornell from a base of extent / 8, three passes (the default minimum size allows three levels,
// but two of them show the pattern at a third of the cost).
struct CornellRun {
    Scene scene = make_builtin_scene("cornell");
    double extent = extent_of(scene);
    PatchMesh base = build_patches(scene, MeshingOptions{extent / 8});
    AdaptiveResult result = adapt(scene, extent / 8, AdaptiveOptions{.max_passes = 3});
};

const CornellRun& cornell() {
    static const CornellRun run = [] {
        CornellRun r;
        std::printf("builtin:cornell, base extent / 8:\n");
        print_passes(r.result.report);
        return r;
    }();
    return run;
}

// Area-weighted mean longest edge of the leaves that `pick` selects.
template <typename Pick>
double mean_edge(const AdaptiveResult& r, Pick pick) {
    double sum = 0.0, area = 0.0;
    for (std::size_t k = 0; k < r.leaves.size(); ++k) {
        if (!pick(k)) continue;
        sum += r.patches.patches[k].area * r.tree.longest_edge(r.leaves[k]);
        area += r.patches.patches[k].area;
    }
    return area > 0.0 ? sum / area : 0.0;
}

TEST(AdaptiveSubdivision, LeavesCoverTheBaseMeshExactly) {
    const CornellRun& run = cornell();
    const AdaptiveResult& r = run.result;
    EXPECT_NEAR(total_area(r.patches), total_area(run.base), 1e-9 * total_area(run.base));
    ASSERT_EQ(r.patches.size(), r.leaves.size());
    ASSERT_EQ(r.system.size(), r.patches.size());
    ASSERT_EQ(r.radiosity.size(), r.patches.size());
    EXPECT_GT(r.patches.size(), 2 * run.base.size()) << "the box has shadows and gradients to refine";
    EXPECT_EQ(r.report.passes.size(), 3u);
    EXPECT_EQ(r.report.stop, AdaptiveStop::max_passes);
    for (std::size_t s = 0; s + 1 < run.base.surface_begin.size(); ++s) {
        double base_area = 0.0, leaf_area = 0.0;
        for (std::uint32_t q = run.base.surface_begin[s]; q < run.base.surface_begin[s + 1]; ++q)
            base_area += run.base.patches[q].area;
        for (std::uint32_t q = r.patches.surface_begin[s]; q < r.patches.surface_begin[s + 1]; ++q)
            leaf_area += r.patches.patches[q].area;
        EXPECT_NEAR(leaf_area, base_area, 1e-9 * base_area) << run.scene.surfaces[s].name;
    }
    // The returned system is the last pass's: a fresh solver on it finds the returned radiosity again.
    const auto solver = make_solver(SolverMethod::conjugate_gradient, r.system, SolverOptions{});
    while (!solver->report().finished()) solver->step();
    for (std::size_t i = 0; i < r.patches.size(); i += 97)
        EXPECT_NEAR(solver->solution()[i].g, r.radiosity[i].g, 1e-9 + 1e-6 * r.radiosity[i].g);
}

// The distance in the floor's plane (x, z) from p to the segment a-b.
double floor_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec2 q(p.x, p.z), u(a.x, a.z), v(b.x, b.z);
    const double t = std::clamp(glm::dot(q - u, v - u) / glm::dot(v - u, v - u), 0.0, 1.0);
    return glm::length(q - (u + t * (v - u)));
}

// Where the blocks stand on the floor: their footprints' edges.
const std::array<std::array<glm::dvec3, 4>, 2> kFootprints = {{
    {{{130, 0, 65}, {82, 0, 225}, {240, 0, 272}, {290, 0, 114}}},
    {{{423, 0, 247}, {265, 0, 296}, {314, 0, 456}, {472, 0, 406}}},
}};

double distance_to_contact(const glm::dvec3& p) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& f : kFootprints)
        for (int k = 0; k < 4; ++k) d = std::min(d, floor_distance(p, f[k], f[(k + 1) % 4]));
    return d;
}

// The share of the light's area that p sees, from a 16 × 16 grid on it.
double light_visibility(const CornellRun& run, const RayScene& rays, const glm::dvec3& p,
                        const glm::dvec3& n) {
    const double offset = ray_offset(run.base);
    int seen = 0;
    for (int i = 0; i < 16; ++i) {
        for (int j = 0; j < 16; ++j) {
            const glm::dvec3 target(213.0 + 130.0 * (i + 0.5) / 16, 548.8 - offset,
                                    227.0 + 105.0 * (j + 0.5) / 16);
            const Ray ray{p + offset * n, 0.0f, target - p - offset * n, 1.0f};
            std::uint8_t blocked = 0;
            rays.occluded(std::span(&ray, 1), std::span(&blocked, 1));
            seen += blocked ? 0 : 1;
        }
    }
    return seen / 256.0;
}

// Leaves along the blocks' contact edges on the floor, and along the edges of the light's shadows on the
// floor, are far smaller than those in the middle of the back wall, where the light changes slowly.
TEST(AdaptiveSubdivision, SplitsGatherAtContactEdgesAndShadowBoundaries) {
    const CornellRun& run = cornell();
    const AdaptiveResult& r = run.result;
    const std::uint32_t floor = surface_named(run.scene, "floor"),
                        back = surface_named(run.scene, "back wall");
    const auto surface = [&r](std::size_t k) { return r.patches.patches[k].surface; };
    const auto exposed = [&r](std::size_t k) { return r.system.area[k] > 0.5 * r.patches.patches[k].area; };
    const double near = run.extent / 28;  // 20 mm
    const double contact = mean_edge(r, [&](std::size_t k) {
        return surface(k) == floor && exposed(k) && distance_to_contact(r.patches.patches[k].centroid) < near;
    });
    const RayScene rays(run.base);
    const double penumbra = mean_edge(r, [&](std::size_t k) {
        if (surface(k) != floor || !exposed(k)) return false;
        const double v =
            light_visibility(run, rays, r.patches.patches[k].centroid, r.patches.patches[k].normal);
        return v > 0.1 && v < 0.9;
    });
    // The middle of the back wall: its central half across, from half to three quarters of its height.
    const double middle = mean_edge(r, [&](std::size_t k) {
        const glm::dvec3 c = r.patches.patches[k].centroid;
        return surface(k) == back && c.x > 139 && c.x < 417 && c.y > 274 && c.y < 412;
    });
    std::printf(
        "area-weighted mean longest edge: floor at contact edges %.1f, floor in the light's penumbra "
        "%.1f, back wall middle %.1f (base %.1f)\n",
        contact, penumbra, middle, run.extent / 8);
    ASSERT_GT(contact, 0.0);
    ASSERT_GT(penumbra, 0.0);
    EXPECT_LT(contact, 0.5 * middle);
    EXPECT_LT(penumbra, 0.5 * middle);
}

// Against a path-traced reference at points, the adaptive result is far more accurate than its base, and
// point by point relative to the local radiosity (where dim corners count as much as lit walls) as accurate
// as a uniform mesh with more patches.
TEST(AdaptiveSubdivision, IsAboutAsAccurateAsAFinerUniformMesh) {
    const CornellRun& run = cornell();
    const test::PointReference reference = test::path_traced_reference(run.scene, run.extent / 24, 64);
    const Solution base = solve_uniform(run.scene, run.extent / 8);
    // The uniform mesh: the coarsest with at least 10 % more patches than the adaptive one.
    double divisions = 16;
    while (count_patches(run.scene, run.extent / divisions) < 1.1 * run.result.patches.size()) divisions += 2;
    const Solution uniform = solve_uniform(run.scene, run.extent / divisions);
    const test::PointError base_error = test::point_error(run.scene, base.mesh, base.radiosity, reference);
    const test::PointError uniform_error =
        test::point_error(run.scene, uniform.mesh, uniform.radiosity, reference);
    const test::PointError adaptive_error =
        test::point_error(run.scene, run.result.patches, run.result.radiosity, reference);
    std::printf(
        "error at %zu points (absolute / relative; reference noise %.4f taken out):\n"
        "  uniform extent/8    %5zu patches          %.4f / %.4f\n"
        "  adaptive            %5zu patches %5.1f s  %.4f / %.4f\n"
        "  uniform extent/%-3.0f  %5zu patches %5.1f s  %.4f / %.4f\n",
        reference.position.size(), test::reference_noise(run.scene, reference), base.mesh.size(),
        base_error.absolute, base_error.relative, run.result.patches.size(), run.result.report.seconds,
        adaptive_error.absolute, adaptive_error.relative, divisions, uniform.mesh.size(), uniform.seconds,
        uniform_error.absolute, uniform_error.relative);
    EXPECT_LT(adaptive_error.absolute, 0.7 * base_error.absolute);
    EXPECT_LT(adaptive_error.relative, 0.5 * base_error.relative);
    // Relative to the local radiosity, which the gradient criterion bounds, it is as accurate as the uniform
    // mesh with more patches (measured: 0.97 of its error with 0.77 of its patches). The absolute error is
    // ruled by the brightest surfaces, the blocks' tops under the light, whose steps of under a quarter the
    // criterion leaves alone (measured: 1.25 times the uniform mesh's).
    EXPECT_LT(adaptive_error.relative, 1.05 * uniform_error.relative);
    EXPECT_LT(adaptive_error.absolute, 1.35 * uniform_error.absolute);
}

// A closed furnace: every wall emits E and reflects ρ alike, so B = E / (1 − ρ) everywhere. Even at a strict
// tolerance the gradient criterion finds nothing to split, and in a convex room there are no shadows.
TEST(AdaptiveSubdivision, AnEvenlyLitFurnaceIsNeverSplit) {
    Scene scene = make_cube();
    for (Surface& s : scene.surfaces) s.material = Material{"glow", glm::dvec3(0.5), glm::dvec3(1.0 / M_PI)};
    const AdaptiveResult r = adapt(scene, 0.25, AdaptiveOptions{.tolerance = 0.02, .max_passes = 3});
    ASSERT_EQ(r.report.passes.size(), 1u);
    EXPECT_EQ(r.report.passes[0].gradient_leaves, 0u);
    EXPECT_EQ(r.report.passes[0].shadow_leaves, 0u);
    EXPECT_EQ(r.report.stop, AdaptiveStop::nothing_to_split);
    EXPECT_EQ(r.patches.size(), 96u);
    for (const glm::dvec3& b : r.radiosity) EXPECT_NEAR(b.g, 2.0, 0.02);
}

// builtin:cube lit from its top face: radiosity falls off down the walls, but nothing casts a shadow.
TEST(AdaptiveSubdivision, AConvexRoomHasGradientsButNoShadows) {
    const AdaptiveResult r = adapt(make_cube(), 0.5, AdaptiveOptions{.tolerance = 0.05, .max_passes = 6});
    std::size_t gradient = 0, shadow = 0, too_small = 0;
    for (const AdaptivePass& p : r.report.passes) {
        gradient += p.gradient_leaves;
        shadow += p.shadow_leaves;
        too_small += p.too_small;
    }
    EXPECT_GT(gradient, 0u);
    EXPECT_EQ(shadow, 0u);
    // The default minimum size is a base patch's longest edge / 8: three levels at most, and the gradient
    // criterion reached them.
    EXPECT_GT(too_small, 0u);
    std::uint32_t deepest = 0;
    for (const std::uint32_t e : r.leaves) deepest = std::max(deepest, r.tree[e].level);
    EXPECT_EQ(deepest, 3u);
}

// min_patch_size: a leaf splits only while its longest edge is at least twice the minimum, so every split
// element's parent had a longest edge ≥ 2 × min_patch_size, and (the Cornell box's quads being nearly
// parallelograms, whose quarters have half their parent's edges) no leaf edge falls below 0.99 × min.
TEST(AdaptiveSubdivision, RespectsTheMinimumPatchSize) {
    const Scene scene = make_builtin_scene("cornell");
    const double extent = extent_of(scene);
    const double min_size = extent / 16;  // the base's extent / 4 halves twice to reach it
    const AdaptiveResult r =
        adapt(scene, extent / 4, AdaptiveOptions{.min_patch_size = min_size, .max_passes = 4});
    std::uint32_t deepest = 0;
    for (const std::uint32_t e : r.leaves) {
        const Element& leaf = r.tree[e];
        deepest = std::max(deepest, leaf.level);
        if (leaf.level == 0) continue;
        EXPECT_GE(r.tree.longest_edge(leaf.parent), 2.0 * min_size * (1.0 - 1e-9));
        EXPECT_GE(r.tree.longest_edge(e), 0.99 * min_size);
    }
    EXPECT_EQ(deepest, 2u);
    EXPECT_GT(r.report.passes.back().too_small + r.report.passes[r.report.passes.size() - 2].too_small, 0u);
}

// The memory budget of the form factors bounds the leaves: they never exceed the most whose pass fits
// (form_factor_memory_estimate); when the chosen splits do not all fit, the most important are made, solved,
// and the loop ends.
TEST(AdaptiveSubdivision, NeverExceedsTheMemoryBudget) {
    const Scene scene = make_builtin_scene("cornell");
    const double extent = extent_of(scene);
    const std::size_t base = count_patches(scene, extent / 8);
    FormFactorOptions ff;
    ff.max_memory_bytes = form_factor_memory_estimate(base + 301, ff.method, kDefaultHemisphereRays);
    EXPECT_EQ(adaptive_leaves_that_fit(ff), base + 301);
    const AdaptiveResult r = adapt(scene, extent / 8, AdaptiveOptions{.max_passes = 4}, ff);
    EXPECT_EQ(r.report.stop, AdaptiveStop::memory_budget);
    ASSERT_EQ(r.report.passes.size(), 2u);
    EXPECT_EQ(r.report.passes[0].split, 100u);  // each split adds three leaves: 100 fit in 301
    EXPECT_EQ(r.patches.size(), base + 300);

    ff.max_memory_bytes = form_factor_memory_estimate(base + 2, ff.method, kDefaultHemisphereRays);
    const AdaptiveResult none = adapt(scene, extent / 8, AdaptiveOptions{}, ff);
    EXPECT_EQ(none.report.stop, AdaptiveStop::memory_budget);
    EXPECT_EQ(none.report.passes.size(), 1u);
    EXPECT_EQ(none.patches.size(), base);
}

// No fixed cap on the leaves: beyond the 20,000 there once were, as many as the budget holds.
TEST(AdaptiveSubdivision, TheLeafBoundIsTheBudgets) {
    FormFactorOptions ff;
    ff.max_memory_bytes = std::size_t{8} << 30;
    const std::size_t fit = adaptive_leaves_that_fit(ff);
    EXPECT_GT(fit, 20'000u);
    EXPECT_LE(form_factor_memory_estimate(fit, ff.method, kDefaultHemisphereRays), ff.max_memory_bytes);
    EXPECT_GT(form_factor_memory_estimate(fit + 1, ff.method, kDefaultHemisphereRays), ff.max_memory_bytes);
    // Analytic rows hold every pair: far fewer leaves in the same budget, about sqrt(8 GB / 8 bytes).
    ff.method = FormFactorMethod::analytic;
    const std::size_t analytic = adaptive_leaves_that_fit(ff);
    EXPECT_LT(analytic, fit);
    EXPECT_LE(form_factor_memory_estimate(analytic, ff.method, kDefaultAnalyticRays), ff.max_memory_bytes);
    EXPECT_GT(form_factor_memory_estimate(analytic + 1, ff.method, kDefaultAnalyticRays),
              ff.max_memory_bytes);
    EXPECT_LT(analytic, 32'800u);
}

TEST(AdaptiveSubdivision, RejectsBadOptions) {
    const Scene scene = make_cube();
    const PatchMesh base = build_patches(scene, MeshingOptions{0.5});
    const auto run = [&](const AdaptiveOptions& options) {
        return [&scene, &base, options](const std::string&) {
            subdivide_adaptively(scene, base, FormFactorOptions{}, SolverMethod::jacobi, SolverOptions{},
                                 options);
        };
    };
    test::expect_input_error(run({.tolerance = 0.0}), "tolerance", {"tolerance"});
    test::expect_input_error(run({.max_passes = 0}), "passes", {"pass"});
    test::expect_input_error(run({.min_patch_size = -1.0}), "min size", {"minimum patch size"});
}

// A base mesh whose own form factors exceed the budget is refused before any pass, with the figures and a
// coarser patch size, as the uniform pass is.
TEST(AdaptiveSubdivision, ABaseOverTheBudgetIsRefusedWithTheFigures) {
    const Scene scene = make_cube();
    const PatchMesh base = build_patches(scene, MeshingOptions{0.5});
    ASSERT_EQ(base.size(), 24u);
    FormFactorOptions ff;
    ff.patch_size = 0.5;
    ff.count_patches_at = [&scene](double size) { return count_patches(scene, size); };
    ff.max_memory_bytes = form_factor_memory_estimate(23, ff.method, kDefaultHemisphereRays);
    Progress progress;
    try {
        subdivide_adaptively(scene, base, ff, SolverMethod::jacobi, SolverOptions{}, AdaptiveOptions{},
                             &progress);
        FAIL() << "a budget one patch short was accepted";
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.patches, 24u);
        EXPECT_EQ(e.needed_bytes, form_factor_memory_estimate(24, ff.method, kDefaultHemisphereRays));
        EXPECT_EQ(e.budget_bytes, ff.max_memory_bytes);
        // 24 patches of 0.5 become 6 of 1.0: the next size up that fits.
        EXPECT_GT(e.coarser_patch_size, 0.5);
        EXPECT_LE(form_factor_memory_estimate(count_patches(scene, e.coarser_patch_size), ff.method,
                                              kDefaultHemisphereRays),
                  ff.max_memory_bytes);
    }
    EXPECT_EQ(progress.state().stage, "") << "refused before any pass began";
}

TEST(AdaptiveSubdivision, StopsWhenCancelled) {
    const Scene scene = make_cube();
    Progress progress;
    progress.cancel();
    EXPECT_THROW(subdivide_adaptively(scene, build_patches(scene, MeshingOptions{0.5}), FormFactorOptions{},
                                      SolverMethod::jacobi, SolverOptions{}, AdaptiveOptions{}, &progress),
                 Cancelled);
}

// The shadow rays are seeded per leaf and source: the same requests on one thread as on several.
TEST(AdaptiveSubdivision, ShadowRequestsDoNotDependOnThreads) {
    const CornellRun& run = cornell();
    const AdaptiveResult& r = run.result;
    const SolvedLeaves leaves{r.tree, r.leaves, r.patches, r.system, r.radiosity};
    const std::vector<ShadowSource> sources = shadow_sources(leaves);
    ASSERT_FALSE(sources.empty());
    const RayScene scene(run.base);
    const ShadowRays rays{run.base, scene, ray_offset(run.base), 7};
    const auto with_threads = [&](std::size_t threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return shadow_excess(leaves, sources, rays, nullptr);
    };
    const std::vector<double> one = with_threads(1);
    EXPECT_EQ(one, with_threads(2));
    EXPECT_GT(std::count_if(one.begin(), one.end(), [](double e) { return e >= 1.0; }), 0);
}

// The figures for the report, on request (RAD_ADAPTIVE_MEASURE=1; a few minutes; RAD_ADAPTIVE_RAYS sets the
// hemisphere rays, RAD_ADAPTIVE_TOLERANCE the tolerance, RAD_ADAPTIVE_UNIFORM=0 skips the uniform meshes):
// patches and time per pass, and the point errors of adaptive and uniform meshes against a
// path-traced reference at 15,118 points.
TEST(AdaptiveSubdivisionMeasure, CornellAgainstUniformMeshes) {
    if (!std::getenv("RAD_ADAPTIVE_MEASURE")) GTEST_SKIP() << "set RAD_ADAPTIVE_MEASURE=1 to measure";
    const Scene scene = make_builtin_scene("cornell");
    const double extent = extent_of(scene);
    FormFactorOptions ff;
    if (const char* rays = std::getenv("RAD_ADAPTIVE_RAYS")) ff.rays = std::atoi(rays);
    AdaptiveOptions options;
    if (const char* tolerance = std::getenv("RAD_ADAPTIVE_TOLERANCE"))
        options.tolerance = std::atof(tolerance);
    const char* uniform = std::getenv("RAD_ADAPTIVE_UNIFORM");
    const auto start = std::chrono::steady_clock::now();
    const test::PointReference reference = test::path_traced_reference(scene, extent / 40, 128);
    std::printf("reference: %zu points x 128 paths, %.1f s, its relative RMS noise %.4f (taken out)\n",
                reference.position.size(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                test::reference_noise(scene, reference));
    std::printf("tolerance %.2f, %d rays\nmesh                 patches  seconds  error: absolute relative\n",
                options.tolerance, ff.rays > 0 ? ff.rays : 4096);
    for (const double d : {8.0, 12.0, 16.0, 24.0, 32.0}) {
        if (uniform && std::string(uniform) == "0") break;
        const Solution u = solve_uniform(scene, extent / d, ff);
        const test::PointError e = test::point_error(scene, u.mesh, u.radiosity, reference);
        std::printf("uniform extent/%-3.0f  %7zu  %7.1f         %.4f   %.4f\n", d, u.mesh.size(), u.seconds,
                    e.absolute, e.relative);
    }
    for (const int passes : {2, 3, 4}) {
        options.max_passes = passes;
        const AdaptiveResult r = adapt(scene, extent / 8, options, ff);
        const test::PointError e = test::point_error(scene, r.patches, r.radiosity, reference);
        std::printf("adaptive, %d passes   %7zu  %7.1f         %.4f   %.4f\n", passes, r.patches.size(),
                    r.report.seconds, e.absolute, e.relative);
        if (passes == 4) print_passes(r.report);
    }
}

}  // namespace
}  // namespace rad
