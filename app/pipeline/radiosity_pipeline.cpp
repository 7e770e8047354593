#include "pipeline/radiosity_pipeline.hpp"

#include <algorithm>

#include "pipeline/form_factor_options.hpp"
#include "rad/util/error.hpp"
#include "rad/util/stopwatch.hpp"

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
    // Bad options fail before the long work.
    if (!automatic_method(options.solver)) check_solver_supported(method_, has_matrix(subdivision_));
    check_solver_options(rad::solver_options(options.solver, 1));
    const Stopwatch clock;
    loaded_ = load_and_mesh(options.scene, base_patch_scale(subdivision_));
    seconds_.mesh = clock.seconds();
    solver_options_ = rad::solver_options(options.solver, loaded_.patches.size());
}

TransportSettings RadiosityPipeline::transport_settings() const {
    TransportSettings settings;
    settings.subdivision = subdivision_;
    settings.form_factors = form_factor_options_for(options_.form_factors, loaded_);
    settings.adaptive = adaptive_options(options_.subdivision, options_.form_factors.seed);
    settings.hierarchical =
        hierarchical_options(options_.subdivision, options_.form_factors.rays, options_.form_factors.seed);
    // An automatic choice solves the passes by bounces; the final solver is chosen once the transport is
    // known.
    settings.pass_method = method_;
    settings.pass_solver = solver_options_;
    return settings;
}

void RadiosityPipeline::prepare(Progress* progress) {
    if (solver_) return;
    const Stopwatch clock;
    built_ = build_scene_transport(loaded_.scene, loaded_.patches, transport_settings(), progress);
    seconds_.form_factors = clock.seconds();
    work_.form_factor_passes += built_.transport->report().form_factor_passes;
    display_.reset();
    solver_options_ = rad::solver_options(options_.solver, patches().size());
    if (automatic_method(options_.solver)) method_ = recommended_method(*built_.transport, solver_options_);
    // Adaptive subdivision's last pass was solved already, but a fresh solver from B = E is what stepping
    // bounces shows.
    solver_ = make_solver(method_, *built_.transport, solver_options_);
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
    const Stopwatch clock;
    const std::size_t steps_before = solver_->report().step;
    run_to_end(*solver_, progress);
    work_.solver_steps += solver_->report().step - steps_before;
    seconds_.solve += clock.seconds();
    return solver_->report();
}

void RadiosityPipeline::restart_solver(SolverMethod method, const SolverOptions& options) {
    prepare();
    solver_ = make_solver(method, *built_.transport, options);
    method_ = method;
    solver_options_ = options;
}

const DisplayMesh& RadiosityPipeline::display() const {
    if (!display_) display_.emplace(build_display_mesh(patches(), options_.display));
    return *display_;
}

EnergyBalance RadiosityPipeline::energy_balance() const {
    return rad::energy_balance(*built_.transport, solver_->solution());
}

std::vector<glm::vec3> RadiosityPipeline::vertex_radiance() const {
    if (!solver_) return std::vector<glm::vec3>(display().vertex_count(), glm::vec3(0.0f));
    return rad::vertex_radiance(display(), solver_->display_solution());
}

}  // namespace rad
