#include "viewer/solver_worker.hpp"

#include "text/input_error_message.hpp"

#include <tbb/task_arena.h>
#include <algorithm>
#include <exception>

#include "rad/camera/camera_view.hpp"
#include "rad/display/display_outline.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/io/scene_export.hpp"
#include "viewer/missing_scene.hpp"
#include "viewer/scene_materials.hpp"

namespace rad {

namespace {

// The work's parallel stages leave one core to the render thread (and to a software rasterizer such as
// llvmpipe), so frames stay short while form factors run.
int work_threads() {
    return std::max(1, tbb::this_task_arena::max_concurrency() - 1);
}

// One call per command kind, for std::visit.
template <class... Calls>
struct Overloaded : Calls... {
    using Calls::operator()...;
};
// Clang before 17 deduces no template arguments for aggregates without a guide.
template <class... Calls>
Overloaded(Calls...) -> Overloaded<Calls...>;

}  // namespace

SolverWorker::SolverWorker(const PipelineOptions& options, std::function<void()> on_change)
    : on_change_(std::move(on_change)), arena_(work_threads()) {
    commands_.add(WorkerCommands::Rebuild{options, 0});
    thread_ = std::thread([this] { loop(); });
}

SolverWorker::~SolverWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        if (progress_) progress_->cancel();
    }
    wake_.notify_all();
    thread_.join();
}

void SolverWorker::request_rebuild(const PipelineOptions& options, std::size_t steps) {
    ask([&] {
        if (progress_) progress_->cancel();  // the old scene's form factors are no longer wanted
        commands_.add(WorkerCommands::Rebuild{options, steps});
    });
}

void SolverWorker::request_steps(std::size_t count) {
    ask([&] { commands_.add_steps(count); });
}

void SolverWorker::set_running(bool running) {
    ask([&] { commands_.set_running(running); });
}

void SolverWorker::request_reset(const std::string& method, double tolerance) {
    ask([&] { commands_.add(WorkerCommands::Reset{method, tolerance, true}); });
}

void SolverWorker::request_colour_mode(ColourMode mode) {
    ask([&] { commands_.add(WorkerCommands::ColourModeSwitch{mode}); });
}

void SolverWorker::request_material_edit(const std::string& name, const glm::dvec3& reflectance,
                                         const glm::dvec3& emitted_radiance) {
    ask([&] { commands_.add(WorkerCommands::MaterialEdit{name, reflectance, emitted_radiance}); });
}

void SolverWorker::request_outside_light(const std::string& sky, const std::string& sun) {
    ask([&] { commands_.add(WorkerCommands::OutsideLight{sky, sun}); });
}

void SolverWorker::request_write(const std::string& path, double exposure) {
    ask([&] { commands_.add(WorkerCommands::Write{path, exposure}); });
}

void SolverWorker::ask(const std::function<void()>& change) {
    {
        std::lock_guard lock(mutex_);
        change();
    }
    wake_.notify_all();
}

void SolverWorker::cancel() {
    std::lock_guard lock(mutex_);
    if (progress_) progress_->cancel();
    commands_.stop_stepping();
}

SolverSnapshot SolverWorker::snapshot() const {
    std::lock_guard lock(mutex_);
    return snapshot_;
}

std::shared_ptr<const Progress> SolverWorker::progress() const {
    std::lock_guard lock(mutex_);
    return progress_;
}

bool SolverWorker::busy() const {
    std::lock_guard lock(mutex_);
    return working_ || commands_.has_next();
}

bool SolverWorker::running() const {
    std::lock_guard lock(mutex_);
    return commands_.running();
}

std::size_t SolverWorker::pending_steps() const {
    std::lock_guard lock(mutex_);
    return commands_.steps();
}

void SolverWorker::loop() {
    while (const std::optional<Command> command = wait_for_command()) {
        const bool completed = run(*command);
        publish_statistics();
        end_job(*command, completed);
        changed();
    }
}

std::optional<SolverWorker::Command> SolverWorker::wait_for_command() {
    std::unique_lock lock(mutex_);
    working_ = false;
    wake_.wait(lock, [this] { return stop_ || commands_.has_next(); });
    if (stop_) return std::nullopt;
    working_ = true;
    progress_ = std::make_shared<Progress>();
    return commands_.take_next();
}

bool SolverWorker::run(const Command& command) {
    const auto run_command = Overloaded{
        [this](const WorkerCommands::Rebuild& c) { rebuild(c); },
        [this](const WorkerCommands::ColourModeSwitch& c) { switch_colour_mode(c.mode); },
        [this](const WorkerCommands::Reset& c) { start_solver(c, false); },
        [this](const WorkerCommands::MaterialEdit& c) { edit_material(c); },
        [this](const WorkerCommands::OutsideLight& c) { edit_outside_light(c); },
        [this](const WorkerCommands::Write& c) { write(c); },
        [this](const WorkerCommands::Step&) { take_step(); },
    };
    try {
        arena_.execute([&] { std::visit(run_command, command); });
        return true;
    } catch (const Cancelled&) {
        fail("cancelled; re-mesh or reset to compute again");
    } catch (const InputError& e) {
        fail(input_error_message(e), true);
    } catch (const std::exception& e) {
        fail(std::string("failed: ") + e.what());
    }
    return false;
}

void SolverWorker::end_job(const Command& command, bool completed) {
    std::lock_guard lock(mutex_);
    progress_.reset();
    if (std::holds_alternative<WorkerCommands::Rebuild>(command) && keep_error_jobs_ > 0) --keep_error_jobs_;
    commands_.end_job(completed);
}

void SolverWorker::changed() {
    ++changes_;
    if (on_change_) on_change_();
}

void SolverWorker::rebuild(const WorkerCommands::Rebuild& request) {
    const PipelineOptions& options = request.options;
    progress_->begin("loading and meshing", 0);
    OpenedScene opened;
    try {
        opened = open_scene(options);
    } catch (const InputError& e) {
        not_opened(e);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        commands_.opened();
        // The previous scene's run ends (a run asked for at the start waits).
        if (pipeline_) commands_.set_running(false);
        commands_.add_steps(request.steps);
    }
    const bool saved = opened.saved_options.has_value();
    const std::string scene = saved ? opened.saved_options->scene.scene : options.scene.scene;
    // The same scene again (another patch size, subdivision or form-factor method): its solution stays
    // shown until the new one has its transport, and a Cancel keeps it.
    if (!saved && pipeline_ && pipeline_->prepared() && scene == shown_scene_) {
        opened.pipeline->prepare(progress_.get());
        show_pipeline(std::move(opened.pipeline), options, std::nullopt);
        display_ = pipeline_->build_display(options_.display, progress_.get());
        start_solver({options_.solver.method, options_.solver.tolerance, false}, true);
        return;
    }
    if (scene != shown_scene_ || !pipeline_) ++scene_version_;
    shown_scene_ = scene;
    show_pipeline(std::move(opened.pipeline), options, std::move(opened.saved_options));
    if (saved) {
        show_saved(opened.saved_steps);
        return;
    }
    show_preview();
    prepare_solver();
    // Built again from the patches: adaptive, hierarchical or clustered leaves are new geometry, and the
    // direct light splits the display's triangles along shadow edges, so it is traced on the unsplit mesh,
    // now with the patches' means kept.
    display_ = pipeline_->build_display(options_.display, progress_.get());
    start_solver({options_.solver.method, options_.solver.tolerance, false}, true);
}

SolverWorker::OpenedScene SolverWorker::open_scene(const PipelineOptions& options) const {
    // A saved solution is shown at once; its transport is rebuilt behind it, so stepping can continue.
    if (!is_saved_solution_path(options.scene.scene))
        return {std::make_unique<RadiosityPipeline>(options), std::nullopt, 0};
    SavedSolution saved = read_saved_solution(options.scene.scene);
    OpenedScene opened;
    opened.saved_options = options_from_solution(saved.solution.settings, options);
    opened.saved_steps = saved.solution.report.steps;
    opened.pipeline =
        std::make_unique<RadiosityPipeline>(std::move(saved), options.scene.scene, options.display);
    return opened;
}

void SolverWorker::not_opened(const InputError& error) {
    std::lock_guard lock(mutex_);
    snapshot_.error = input_error_message(error);
    snapshot_.bad_input = true;
    // This job and the restarted one: that does not hide why the scene did not open.
    if (commands_.restart_interrupted()) keep_error_jobs_ = 2;
}

void SolverWorker::show_pipeline(std::unique_ptr<RadiosityPipeline> pipeline, const PipelineOptions& options,
                                 std::optional<PipelineOptions> saved_options) {
    const DisplayOptions display = options_.display;
    const bool had_pipeline = pipeline_ != nullptr;
    options_ = options;
    if (had_pipeline) options_.display = display;  // a smooth/flat choice made since the start stays
    pipeline_ = std::move(pipeline);
    saved_options_ = std::move(saved_options);
    remesh_unavailable_ = saved_options_ ? missing_scene(saved_options_->scene.scene) : std::string();
    ++opened_;
    materials_ = scene_materials(pipeline_->loaded().scene);
    history_.restart();  // the previous scene's plots and bounces are not this one's
    set_can_step(false);
    std::lock_guard lock(mutex_);
    if (keep_error_jobs_ > 0) return;
    snapshot_.error.clear();
    snapshot_.bad_input = false;
}

void SolverWorker::show_saved(std::size_t saved_steps) {
    display_ = pipeline_->build_display(options_.display, progress_.get());
    publish(true, true);
    publish_statistics();
    prepare_solver();
    // The pipeline's solver continues from the saved radiosity; a reset would start it from the emission.
    // A saved solution's rebuilt elements were checked to be the saved ones, which are drawn already.
    history_.restart(saved_steps);
    history_.add_start(display_, pipeline_->solver().display_solution());
    set_can_step(!pipeline_->solver().report().finished());
    publish(false, true);
}

void SolverWorker::show_preview() {
    // The emission at once, then the emitters' direct light as soon as it is traced, while form factors run.
    DisplayOptions emission_only = options_.display;
    emission_only.direct_light_at_vertices = false;
    display_ = pipeline_->build_display(emission_only);
    publish(true, true);
    publish_statistics();
    if (options_.display.mode != ColourMode::smooth || !options_.display.direct_light_at_vertices) return;
    progress_->begin("direct light", 0);
    display_ = pipeline_->build_display(options_.display);
    // New geometry: the direct light splits the triangles along shadow edges.
    if (!display_.light.direct.vertex.empty()) publish(true, true);
}

void SolverWorker::start_solver(const WorkerCommands::Reset& reset, bool geometry_changed) {
    if (!pipeline_) return;
    prepare_solver();
    options_.solver.method = reset.method;
    options_.solver.tolerance = reset.tolerance;
    SolverOptions solver_options = rad::solver_options(options_.solver, pipeline_->patches().size());
    if (reset.from_emission) solver_options.initial = InitialGuess::emission;
    pipeline_->restart_solver(solver_method(options_.solver), solver_options);
    start_history_from_solver();
    set_can_step(!pipeline_->solver().report().finished());
    publish(geometry_changed, true);
    std::lock_guard lock(mutex_);
    if (keep_error_jobs_ == 0) snapshot_.error.clear();
}

void SolverWorker::edit_material(const WorkerCommands::MaterialEdit& edit) {
    if (!pipeline_) return;
    prepare_solver();
    pipeline_->edit_material(edit.name, edit.reflectance, edit.emitted_radiance);
    materials_ = scene_materials(pipeline_->loaded().scene);
    run_after_edit();
}

void SolverWorker::edit_outside_light(const WorkerCommands::OutsideLight& light) {
    if (!pipeline_) return;
    prepare_solver();
    pipeline_->edit_outside_light(light.sky, light.sun, progress_.get());
    options_.scene.sky = light.sky;
    options_.scene.sun = light.sun;
    run_after_edit();
}

void SolverWorker::run_after_edit() {
    // The display's light changes with an edit; its geometry too where the emitters changed (their light
    // at the vertices splits triangles along shadow edges).
    const bool new_geometry = pipeline_->redraw_display(display_, options_.display, progress_.get());
    start_history_from_solver();
    const bool can_step = !pipeline_->solver().report().finished();
    set_can_step(can_step);
    {
        std::lock_guard lock(mutex_);
        commands_.set_running(can_step);  // live: the light settles to the edit without being asked
        snapshot_.error.clear();
    }
    // Textured ranges carry their material's colours with the geometry.
    publish(new_geometry || !display_.textured.empty(), true);
}

void SolverWorker::write(const WorkerCommands::Write& file) {
    if (!pipeline_) return;
    std::string error;
    try {
        if (is_saved_solution_path(file.path)) {
            if (!pipeline_->prepared())
                throw InputError(file.path + ": nothing to save before the form factors are known");
            write_saved_solution(file.path, pipeline_->saved_solution());
        } else if (!export_format(file.path)) {
            throw InputError(file.path + ": save as .radiosity, or export as .ply, .gltf or .glb");
        } else {
            // The colours drawn now, published with display_.
            std::shared_ptr<const ViewerRadiance> shown;
            {
                std::lock_guard lock(mutex_);
                shown = snapshot_.radiance;
            }
            if (!shown) throw InputError(file.path + ": nothing to export before the scene is shown");
            export_scene(file.path, display_, shown->cumulative, ExportOptions{.exposure = file.exposure});
        }
    } catch (const InputError& e) {
        error = input_error_message(e);
    } catch (const std::exception& e) {
        error = file.path + ": " + e.what();
    }
    std::lock_guard lock(mutex_);
    snapshot_.written = error.empty() ? "wrote " + file.path : std::string();
    if (!error.empty()) snapshot_.error = error;
}

std::vector<glm::dvec3> SolverWorker::shown_radiosity() const {
    // A solution (a saved one is shown while its transport is rebuilt). While form factors run for a new
    // scene: the emission, and the emitters' direct light at the vertices once it is traced.
    if (pipeline_->has_solution()) return pipeline_->solution().shown_radiosity;
    return pipeline_->preview_radiosity();
}

std::optional<double> SolverWorker::shown_direct_share() const {
    if (!pipeline_->has_solution()) return 1.0;
    return std::nullopt;
}

void SolverWorker::take_step() {
    if (!pipeline_ || !pipeline_->prepared()) return;
    std::vector<glm::dvec3> before = pipeline_->solver().display_solution();
    const StepReport report = pipeline_->step();
    history_.add_step(display_, std::move(before), pipeline_->solver().display_solution(), report);
    if (report.finished()) {
        std::lock_guard lock(mutex_);
        commands_.stop_stepping();
    }
    set_can_step(!report.finished());
    publish(false, true);
}

void SolverWorker::switch_colour_mode(ColourMode mode) {
    if (!pipeline_ || options_.display.mode == mode) return;
    options_.display.mode = mode;
    display_ = pipeline_->build_display(options_.display, progress_.get());
    history_.recolour(display_);
    publish(true, true);
}

void SolverWorker::prepare_solver() {
    pipeline_->prepare(progress_.get());
}

void SolverWorker::start_history_from_solver() {
    history_.restart();
    // Step 0: the solver's first radiosity (the emission, or its first guess) is the newest light.
    history_.add_start(display_, pipeline_->solver().display_solution());
}

void SolverWorker::set_can_step(bool can_step) {
    std::lock_guard lock(mutex_);
    commands_.set_can_step(can_step);
}

void SolverWorker::publish(bool geometry_changed, bool with_radiance) {
    // Built before taking the lock, which the render thread takes every frame.
    std::shared_ptr<ViewerGeometry> geometry = geometry_changed ? shown_geometry() : nullptr;
    std::shared_ptr<ViewerRadiance> radiance = with_radiance ? shown_radiance() : nullptr;
    {
        std::lock_guard lock(mutex_);
        if (geometry) snapshot_.geometry = std::move(geometry);
        snapshot_.radiance = std::move(radiance);
    }
    changed();
}

std::shared_ptr<ViewerGeometry> SolverWorker::shown_geometry() const {
    auto geometry = std::make_shared<ViewerGeometry>();
    geometry->positions = display_.positions;
    const auto* first = reinterpret_cast<const std::uint32_t*>(display_.triangles.data());
    geometry->triangles.assign(first, first + display_.triangles.size() * 3);
    geometry->outline = patch_outline(display_);
    geometry->texcoords = display_.texcoords;
    geometry->triangle_material = triangle_materials(pipeline_->loaded().scene, *materials_, display_);
    geometry->textured = display_.textured;
    geometry->bounds = bounding_box(pipeline_->loaded().scene);
    geometry->scene_camera = scene_camera(pipeline_->loaded().scene);
    geometry->scene_version = scene_version_;
    return geometry;
}

std::shared_ptr<ViewerRadiance> SolverWorker::shown_radiance() const {
    auto radiance = std::make_shared<ViewerRadiance>();
    const std::vector<glm::dvec3> shown = shown_radiosity();
    const std::vector<glm::dvec3>& previous = history_.previous_solution();
    const bool stepped = pipeline_->prepared() && previous.size() == shown.size();
    radiance->cumulative = stepped ? stepped_vertex_radiance(display_, shown, previous)
                                   : vertex_radiance(display_, shown, shown_direct_share());
    if (pipeline_->prepared()) {
        radiance->bounces.assign(history_.vertex_bounces().begin(), history_.vertex_bounces().end());
        radiance->first_bounce = history_.first_bounce();
        radiance->step = history_.first_step() + pipeline_->solver().report().step;
    } else if (pipeline_->has_solution()) {
        // Before the transport is rebuilt: the saved state, with no bounce history.
        radiance->step = pipeline_->solution().report.steps;
    }
    return radiance;
}

void SolverWorker::publish_statistics() {
    ViewerStatistics statistics;
    if (pipeline_) {
        statistics.scene = options_.scene.scene;
        statistics.saved_options = saved_options_;
        statistics.remesh_unavailable = remesh_unavailable_;
        statistics.opened = opened_;
        statistics.warnings = pipeline_->loaded().scene.warnings;
        statistics.materials = materials_;
        statistics.patches = pipeline_->patches().size();
        statistics.subdivision = std::string(subdivision_name(pipeline_->subdivision()));
        statistics.patch_size = pipeline_->loaded().patch_size;
        statistics.seconds = pipeline_->seconds();
        statistics.method = pipeline_->method();
        statistics.prepared = pipeline_->prepared();
        statistics.form_factor_passes = pipeline_->work().form_factor_passes;
        if (statistics.prepared) {
            const TransportReport transport = pipeline_->transport().report();
            statistics.interactions = transport.interactions;
            statistics.interaction_name = transport.interaction_name;
            statistics.status = pipeline_->solver().report().status;
            statistics.status_message = pipeline_->solver().status_message();
        }
        statistics.log_residual = history_.log_residual();
        statistics.log_unshot = history_.log_unshot();
    }
    {
        std::lock_guard lock(mutex_);
        snapshot_.statistics = std::move(statistics);
    }
    changed();
}

void SolverWorker::fail(const std::string& message, bool bad_input) {
    std::lock_guard lock(mutex_);
    snapshot_.error = message;
    snapshot_.bad_input = bad_input;
    commands_.stop_stepping();
}

}  // namespace rad
