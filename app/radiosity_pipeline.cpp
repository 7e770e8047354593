#include "radiosity_pipeline.hpp"

#include <algorithm>

#include "form_factor_options.hpp"
#include "rad/error.hpp"
#include "rad/stopwatch.hpp"

namespace rad {

void add_pipeline_options(CLI::App& command, PipelineOptions& options) {
    add_scene_options(command, options.scene);
    add_form_factor_options(command, options.form_factors);
    add_solver_options(command, options.solver);
    add_subdivision_options(command, options.subdivision);
}

RadiosityPipeline::RadiosityPipeline(const PipelineOptions& options) : options_(options) {
    subdivision_ = parse_subdivision(options.subdivision.method);
    method_ = solver_method(options.solver);
    if (subdivision_ == Subdivision::hierarchical && !automatic_method(options.solver) &&
        method_ != SolverMethod::jacobi) {
        throw InputError(
            "--solver " + options.solver.method +
            ": hierarchical radiosity gathers along its links by jacobi steps; use --solver jacobi "
            "or auto, or --subdivision uniform");
    }
    check_solver_options(rad::solver_options(options.solver, 1));  // bad options fail before the long work
    const Stopwatch clock;
    const double base_scale = subdivision_ == Subdivision::hierarchical ? kHierarchicalBaseScale
                              : subdivision_ == Subdivision::adaptive   ? kAdaptiveBaseScale
                                                                        : 1.0;
    loaded_ = load_and_mesh(options.scene, base_scale);
    seconds_.mesh = clock.seconds();
    solver_options_ = rad::solver_options(options.solver, loaded_.patches.size());
}

void RadiosityPipeline::prepare(Progress* progress) {
    if (solver_) return;
    if (subdivision_ == Subdivision::hierarchical) return prepare_hierarchical(progress);
    if (subdivision_ == Subdivision::adaptive) return prepare_adaptive(progress);
    prepare_uniform(progress);
}

void RadiosityPipeline::prepare_adaptive(Progress* progress) {
    const Stopwatch clock;
    const SolverMethod method =
        automatic_method(options_.solver) ? SolverMethod::jacobi : solver_method(options_.solver);
    AdaptiveResult result = subdivide_adaptively(
        loaded_.scene, loaded_.patches, form_factor_options_for(options_.form_factors, loaded_), method,
        solver_options_, adaptive_options(options_.subdivision, options_.form_factors.seed), progress);
    work_.form_factor_passes += result.report.passes.size();
    seconds_.form_factors = clock.seconds();
    adaptive_report_ = result.report;
    adaptive_patches_.emplace(std::move(result.patches));
    use_patches(*adaptive_patches_);
    form_factor_report_ = FormFactorReport{};
    form_factor_report_.seconds = seconds_.form_factors;
    form_factor_report_.nonzeros = result.system.form_factors.nonzeros();
    form_factor_report_.memory_bytes = result.system.form_factors.memory_bytes();
    const FormFactorMatrix& f = result.system.form_factors;
    form_factor_report_.min_row_sum = f.rows() ? 1e300 : 0.0;
    for (std::size_t i = 0; i < f.rows(); ++i) {
        double sum = 0.0;
        for (std::uint64_t k = f.row_begin[i]; k < f.row_begin[i + 1]; ++k) sum += f.value[k];
        form_factor_report_.min_row_sum = std::min(form_factor_report_.min_row_sum, sum);
        form_factor_report_.max_row_sum = std::max(form_factor_report_.max_row_sum, sum);
    }
    system_.emplace(std::move(result.system));
    if (automatic_method(options_.solver)) method_ = recommended_method(*system_, solver_options_);
    // The last pass's solution is known, but a fresh solver from B = E is what stepping bounces shows.
    solver_ = make_solver(method_, *system_, solver_options_);
}

void RadiosityPipeline::use_patches(const PatchMesh& patches) {
    patches_ = &patches;
    display_.reset();
    solver_options_ = rad::solver_options(options_.solver, patches.size());
}

void RadiosityPipeline::prepare_hierarchical(Progress* progress) {
    const Stopwatch clock;
    const HierarchicalOptions options =
        hierarchical_options(options_.subdivision, options_.form_factors.rays, options_.form_factors.seed);
    hierarchy_ =
        build_hierarchical_system(loaded_.scene, loaded_.patches, options, &hierarchical_report_, progress);
    ++work_.form_factor_passes;
    seconds_.form_factors = clock.seconds();
    form_factor_report_ = FormFactorReport{};
    form_factor_report_.seconds = seconds_.form_factors;
    form_factor_report_.memory_bytes = hierarchical_report_.memory_bytes;
    form_factor_report_.nonzeros = hierarchical_report_.links;
    form_factor_report_.rays = hierarchical_report_.rays;
    use_patches(hierarchy_->leaf_patches);
    system_.emplace(hierarchy_->leaf_system);
    method_ = SolverMethod::jacobi;
    solver_ = make_hierarchical_solver(*hierarchy_, solver_options_);
}

void RadiosityPipeline::prepare_uniform(Progress* progress) {
    const Stopwatch clock;
    FormFactorMatrix form_factors =
        compute_form_factors(loaded_.patches, form_factor_options_for(options_.form_factors, loaded_),
                             &form_factor_report_, progress);
    ++work_.form_factor_passes;
    seconds_.form_factors = clock.seconds();
    system_.emplace(make_radiosity_system(loaded_.scene, loaded_.patches, std::move(form_factors)));
    if (automatic_method(options_.solver)) method_ = recommended_method(*system_, solver_options_);
    solver_ = make_solver(method_, *system_, solver_options_);
}

StepReport RadiosityPipeline::step() {
    prepare();
    const Stopwatch clock;
    const StepReport report = solver_->step();
    ++work_.solver_steps;
    seconds_.solve += clock.seconds();
    return report;
}

const StepReport& RadiosityPipeline::solve(Progress* progress) {
    prepare(progress);
    if (progress) progress->begin("solving", solver_options_.max_steps);
    while (!solver_->report().finished()) {
        if (progress && progress->cancelled()) throw Cancelled{};
        step();
        if (progress) progress->advance();
    }
    return solver_->report();
}

void RadiosityPipeline::restart_solver(SolverMethod method, const SolverOptions& options) {
    prepare();
    if (hierarchy_) {
        solver_ = make_hierarchical_solver(*hierarchy_, options);
        solver_options_ = options;
        return;
    }
    solver_ = make_solver(method, *system_, options);
    method_ = method;
    solver_options_ = options;
}

const DisplayMesh& RadiosityPipeline::display() const {
    if (!display_) display_.emplace(build_display_mesh(patches(), options_.display));
    return *display_;
}

EnergyBalance RadiosityPipeline::energy_balance() const {
    if (hierarchy_) return hierarchical_energy_balance(*hierarchy_, solver_->solution());
    return rad::energy_balance(*system_, solver_->solution());
}

std::vector<glm::vec3> RadiosityPipeline::vertex_radiance() const {
    if (!solver_) return std::vector<glm::vec3>(display().vertex_count(), glm::vec3(0.0f));
    return rad::vertex_radiance(display(), solver_->display_solution());
}

}  // namespace rad
