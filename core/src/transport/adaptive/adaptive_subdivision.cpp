#include "rad/transport/adaptive/adaptive_subdivision.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "rad/ray/ray_scene.hpp"
#include "rad/util/error.hpp"
#include "rad/util/stopwatch.hpp"
#include "ray/ray_offset.hpp"
#include "transport/adaptive/adaptive_gradient.hpp"
#include "transport/adaptive/adaptive_selection.hpp"
#include "transport/adaptive/adaptive_shadow.hpp"
#include "transport/uniform/form_factors_memory.hpp"

namespace rad {

namespace {

// The rays per row compute_form_factors takes for `ff` (a negative count is its to refuse).
int pass_rays(const FormFactorOptions& ff) {
    if (ff.rays > 0) return ff.rays;
    return ff.method == FormFactorMethod::hemisphere ? kDefaultHemisphereRays : kDefaultAnalyticRays;
}

void check_options(const AdaptiveOptions& options) {
    if (!(options.min_patch_size >= 0.0) || !std::isfinite(options.min_patch_size))
        throw InputError("adaptive subdivision: the minimum patch size must be finite and at least 0");
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
        throw InputError("adaptive subdivision: the tolerance must be finite and above 0");
    if (options.max_passes < 1) throw InputError("adaptive subdivision: at least one pass is needed");
}

struct PassSolution {
    UniformTransport system;
    std::vector<glm::dvec3> radiosity;
};

std::string pass_stage(const AdaptivePass& pass, int number, const char* what) {
    return "adaptive pass " + std::to_string(number) + " (" + std::to_string(pass.patches) +
           " patches): " + what;
}

// Form factors over the leaves, their system, and a solve run to its end.
PassSolution solve_pass(const Scene& scene, const PatchMesh& mesh, const FormFactorOptions& ff,
                        SolverMethod method, const SolverOptions& solver_options, int number,
                        AdaptivePass& pass, Progress* progress) {
    pass.patches = mesh.size();
    const Stopwatch form_factor_clock;
    FormFactorReport report;
    FormFactorMatrix form_factors = compute_form_factors(mesh, ff, &report, progress);
    PassSolution out{make_uniform_transport(scene, mesh, std::move(form_factors), report), {}};
    pass.form_factor_seconds = form_factor_clock.seconds();
    const Stopwatch solve_clock;
    // The step limit bounds the solve, which usually converges far sooner: no share or estimate from it.
    if (progress)
        progress->begin(pass_stage(pass, number, "solving"), solver_options.max_steps,
                        ProgressTotal::at_most);
    {
        const std::unique_ptr<Solver> solver = make_solver(method, out.system, solver_options);
        const StepReport& solved = run_to_end(*solver, progress);
        pass.solver_steps = solved.step;
        pass.solver_status = solved.status;
        out.radiosity.assign(solver->solution().begin(), solver->solution().end());
    }
    pass.solve_seconds = solve_clock.seconds();
    return out;
}

// The rays per row of a hemisphere estimate, whose noise the gradient criterion discounts; 0 for analytic
// form factors, whose noise is far smaller.
int noise_rays_of(const FormFactorOptions& ff) {
    if (ff.method != FormFactorMethod::hemisphere) return 0;
    return ff.rays > 0 ? ff.rays : kDefaultHemisphereRays;
}

SplitChoice choose_pass_splits(const SolvedLeaves& leaves, const ShadowRays& rays, int noise_rays,
                               const AdaptiveOptions& options, std::size_t max_leaves, int number,
                               AdaptivePass& pass, AdaptiveReport& report, Progress* progress) {
    const Stopwatch clock;
    const std::vector<double> gradient =
        gradient_excess(leaves, options.tolerance, radiosity_noise(leaves, noise_rays));
    const std::vector<ShadowSource> sources = shadow_sources(leaves);
    report.shadow_sources = sources.size();
    if (progress) progress->begin(pass_stage(pass, number, "finding shadow boundaries"), leaves.mesh.size());
    const std::vector<double> shadow = shadow_excess(leaves, sources, rays, progress);
    if (progress && progress->cancelled()) throw Cancelled{};
    SplitChoice choice = choose_splits(leaves.tree, leaves.elements, SplitRequests{gradient, shadow},
                                       options.min_patch_size, max_leaves);
    pass.gradient_leaves = choice.gradient;
    pass.shadow_leaves = choice.shadow;
    pass.too_small = choice.too_small;
    pass.split = choice.leaves.size();
    pass.criteria_seconds = clock.seconds();
    return choice;
}

}  // namespace

std::string_view adaptive_stop_name(AdaptiveStop stop) {
    switch (stop) {
        case AdaptiveStop::nothing_to_split:
            return "nothing to split";
        case AdaptiveStop::max_passes:
            return "max passes";
        case AdaptiveStop::memory_budget:
            return "memory budget";
    }
    return "unknown";
}

std::size_t adaptive_leaves_that_fit(const FormFactorOptions& ff) {
    // Leaves are 32-bit indices of the form factors' columns, with the top values reserved.
    constexpr std::size_t kMostLeaves = std::numeric_limits<std::uint32_t>::max() - 3;
    const std::size_t budget = memory_budget_bytes(ff.max_memory_bytes);
    if (budget == 0) return kMostLeaves;  // the machine would not say: no budget, as for uniform patches
    return form_factor_patches_that_fit(budget, ff.method, pass_rays(ff), kMostLeaves);
}

AdaptiveResult subdivide_adaptively(const Scene& scene, const PatchMesh& base, const FormFactorOptions& ff,
                                    SolverMethod method, const SolverOptions& solver,
                                    const AdaptiveOptions& options, Progress* progress) {
    const Stopwatch clock;
    check_options(options);
    check_solver_options(solver);  // before the first pass's form factors, not after
    // The first pass is the base mesh's: refused now, with a patch size that fits, if it cannot be made.
    if (ff.rays >= 0) check_memory_budget(base, ff, pass_rays(ff));
    const std::size_t max_leaves = adaptive_leaves_that_fit(ff);
    ElementTree tree(base);
    const RayScene ray_scene(base);  // the leaves cover the base patches exactly: the same geometry
    const ShadowRays rays{base, ray_scene, ray_offset(base), options.seed};
    AdaptiveReport report;
    bool budget_spent = false;
    for (int number = 1;; ++number) {
        std::vector<std::uint32_t> leaves = tree.leaves();
        PatchMesh mesh = tree.leaf_mesh(leaves);
        AdaptivePass& pass = report.passes.emplace_back();
        if (progress) {
            progress->begin("adaptive pass " + std::to_string(number) + " of at most " +
                                std::to_string(options.max_passes),
                            0);
            progress->note(std::to_string(mesh.size()) + " patches (at most " + std::to_string(max_leaves) +
                           " within the memory budget): form factors, then a solve");
        }
        PassSolution solved = solve_pass(scene, mesh, ff, method, solver, number, pass, progress);
        std::optional<AdaptiveStop> stop;
        SplitChoice choice;
        if (budget_spent) {
            stop = AdaptiveStop::memory_budget;
        } else if (number >= options.max_passes) {
            stop = AdaptiveStop::max_passes;
        } else {
            const SolvedLeaves solved_leaves{tree, leaves, mesh, solved.system, solved.radiosity};
            choice = choose_pass_splits(solved_leaves, rays, noise_rays_of(ff), options, max_leaves, number,
                                        pass, report, progress);
            if (choice.leaves.empty())
                stop = choice.over_budget ? AdaptiveStop::memory_budget : AdaptiveStop::nothing_to_split;
        }
        if (stop) {
            report.stop = *stop;
            report.seconds = clock.seconds();
            return AdaptiveResult{std::move(tree),          std::move(leaves),           std::move(mesh),
                                  std::move(solved.system), std::move(solved.radiosity), std::move(report)};
        }
        budget_spent = choice.over_budget;
        for (const std::uint32_t i : choice.leaves) tree.split(leaves[i]);
    }
}

}  // namespace rad
