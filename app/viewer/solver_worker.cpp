#include "viewer/solver_worker.hpp"

#include "text/input_error_message.hpp"

#include <tbb/task_arena.h>
#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <system_error>

#include "rad/camera/camera_view.hpp"
#include "rad/display/display_outline.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/io/scene_export.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

// Steps whose light alone the panel can show: Jacobi's light is mostly in its first dozens of bounces, and
// each kept step costs a copy of the solution (and of the colours).
constexpr std::size_t kKeptBounces = 64;

// The work's parallel stages leave one core to the render thread (and to a software rasterizer such as
// llvmpipe), so frames stay short while form factors run.
int work_threads() {
    return std::max(1, tbb::this_task_arena::max_concurrency() - 1);
}

float log10_or_floor(double value) {
    return static_cast<float>(std::log10(std::max(value, 1e-30)));
}

std::vector<glm::dvec3> positive_difference(std::span<const glm::dvec3> now,
                                            std::span<const glm::dvec3> before) {
    std::vector<glm::dvec3> difference(now.begin(), now.end());
    if (before.size() != now.size()) return difference;  // the first step: the emission itself
    for (std::size_t i = 0; i < now.size(); ++i)
        difference[i] = glm::max(now[i] - before[i], glm::dvec3(0.0));
    return difference;
}

// Re-meshing a saved solution loads the scene it was solved from, which the file names but does not hold as
// a file: it may have moved since.
std::string missing_scene(const std::string& source) {
    if (source.starts_with("builtin:")) return {};
    std::error_code error;
    if (std::filesystem::is_regular_file(source, error)) return {};
    return "the scene this solution was solved from, " + source + ", is not found";
}

// The scene's materials by name, in the order of their first surface.
std::shared_ptr<const std::vector<ViewerMaterial>> scene_materials(const Scene& scene) {
    auto materials = std::make_shared<std::vector<ViewerMaterial>>();
    for (const Surface& surface : scene.surfaces) {
        const Material& m = surface.material;
        auto found = std::find_if(materials->begin(), materials->end(),
                                  [&](const ViewerMaterial& v) { return v.name == m.name; });
        if (found == materials->end()) {
            materials->push_back({m.name, m.reflectance, m.emission, m.texture != nullptr, 0.0});
            found = materials->end() - 1;
        }
        found->area += surface_area(surface.mesh);
    }
    return materials;
}

std::vector<std::uint32_t> triangle_materials(const Scene& scene,
                                              const std::vector<ViewerMaterial>& materials,
                                              const DisplayMesh& display) {
    std::vector<std::uint32_t> of_surface(scene.surfaces.size(), 0);
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const auto found = std::find_if(materials.begin(), materials.end(), [&](const ViewerMaterial& v) {
            return v.name == scene.surfaces[s].material.name;
        });
        of_surface[s] = static_cast<std::uint32_t>(found - materials.begin());
    }
    std::vector<std::uint32_t> triangle(display.triangle_patch.size());
    for (std::size_t t = 0; t < triangle.size(); ++t)
        triangle[t] = of_surface[display.patch_surface[display.triangle_patch[t]]];
    return triangle;
}

}  // namespace

SolverWorker::SolverWorker(const PipelineOptions& options, std::function<void()> on_change)
    : on_change_(std::move(on_change)), arena_(work_threads()) {
    pending_rebuild_ = Rebuild{options, 0};
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
    {
        std::lock_guard lock(mutex_);
        if (progress_) progress_->cancel();  // the old scene's form factors are no longer wanted
        // Started again should the new scene not open.
        if (current_rebuild_ && !interrupted_rebuild_) interrupted_rebuild_ = current_rebuild_;
        pending_rebuild_ = Rebuild{options, steps};
    }
    wake_.notify_all();
}

void SolverWorker::request_steps(std::size_t count) {
    {
        std::lock_guard lock(mutex_);
        pending_steps_ += count;
    }
    wake_.notify_all();
}

void SolverWorker::set_running(bool running) {
    {
        std::lock_guard lock(mutex_);
        running_ = running;
    }
    wake_.notify_all();
}

void SolverWorker::request_reset(const std::string& method, double tolerance) {
    {
        std::lock_guard lock(mutex_);
        pending_reset_ = Reset{method, tolerance, true};
        pending_steps_ = 0;
        running_ = false;
    }
    wake_.notify_all();
}

void SolverWorker::request_colour_mode(ColourMode mode) {
    {
        std::lock_guard lock(mutex_);
        pending_colour_mode_ = mode;
    }
    wake_.notify_all();
}

void SolverWorker::request_material_edit(const std::string& name, const glm::dvec3& reflectance,
                                         const glm::dvec3& emitted_radiance) {
    {
        std::lock_guard lock(mutex_);
        std::erase_if(pending_edits_, [&](const MaterialEdit& e) { return e.name == name; });
        pending_edits_.push_back({name, reflectance, emitted_radiance});
    }
    wake_.notify_all();
}

void SolverWorker::request_outside_light(const std::string& sky, const std::string& sun) {
    {
        std::lock_guard lock(mutex_);
        pending_outside_ = std::make_pair(sky, sun);
    }
    wake_.notify_all();
}

void SolverWorker::request_write(const std::string& path, double exposure) {
    {
        std::lock_guard lock(mutex_);
        pending_writes_.push_back({path, exposure});
    }
    wake_.notify_all();
}

void SolverWorker::cancel() {
    std::lock_guard lock(mutex_);
    if (progress_) progress_->cancel();
    pending_steps_ = 0;
    running_ = false;
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
    return working_ || has_work();
}

bool SolverWorker::running() const {
    std::lock_guard lock(mutex_);
    return running_;
}

std::size_t SolverWorker::pending_steps() const {
    std::lock_guard lock(mutex_);
    return pending_steps_;
}

bool SolverWorker::has_work() const {
    return pending_rebuild_ || pending_colour_mode_ || pending_reset_ || !pending_edits_.empty() ||
           pending_outside_ || !pending_writes_.empty() || (can_step_ && (pending_steps_ > 0 || running_));
}

void SolverWorker::loop() {
    for (;;) {
        std::optional<Rebuild> rebuild_request;
        std::optional<ColourMode> colour_mode;
        std::optional<Reset> reset;
        std::optional<MaterialEdit> edit;
        std::optional<Write> file;
        std::optional<std::pair<std::string, std::string>> outside;
        {
            std::unique_lock lock(mutex_);
            working_ = false;
            wake_.wait(lock, [this] { return stop_ || has_work(); });
            if (stop_) return;
            working_ = true;
            // Order matters: a new scene makes every other request moot; a display switch and a reset keep
            // the steps asked for after them.
            if (pending_rebuild_) {
                rebuild_request = std::move(pending_rebuild_);
                pending_rebuild_.reset();
                current_rebuild_ = rebuild_request;
            } else if (pending_colour_mode_) {
                colour_mode = pending_colour_mode_;
                pending_colour_mode_.reset();
            } else if (pending_reset_) {
                reset = pending_reset_;
                pending_reset_.reset();
            } else if (!pending_edits_.empty()) {
                edit = pending_edits_.front();
                pending_edits_.erase(pending_edits_.begin());
            } else if (pending_outside_) {
                outside = std::move(pending_outside_);
                pending_outside_.reset();
            } else if (!pending_writes_.empty()) {
                file = pending_writes_.front();
                pending_writes_.erase(pending_writes_.begin());
            } else if (pending_steps_ > 0) {
                --pending_steps_;
            }
            progress_ = std::make_shared<Progress>();
        }
        bool finished = false;
        try {
            arena_.execute([&] {
                if (rebuild_request) {
                    rebuild(*rebuild_request);
                } else if (colour_mode) {
                    switch_colour_mode(*colour_mode);
                } else if (reset) {
                    reset_solver(*reset);
                } else if (edit) {
                    edit_material(*edit);
                } else if (outside) {
                    edit_outside_light(*outside);
                } else if (file) {
                    write(*file);
                } else {
                    take_step();
                }
            });
            finished = true;
        } catch (const Cancelled&) {
            fail("cancelled; re-mesh or reset to compute again");
        } catch (const InputError& e) {
            fail(input_error_message(e), true);
        } catch (const std::exception& e) {
            fail(std::string("failed: ") + e.what());
        }
        publish_statistics();
        {
            std::lock_guard lock(mutex_);
            progress_.reset();
            // A rebuild that ran to its end need not run again.
            if (current_rebuild_ && finished) interrupted_rebuild_.reset();
            if (current_rebuild_ && keep_error_jobs_ > 0) --keep_error_jobs_;
            current_rebuild_.reset();
        }
        changed();
    }
}

void SolverWorker::changed() {
    ++changes_;
    if (on_change_) on_change_();
}

void SolverWorker::rebuild(const Rebuild& request) {
    const PipelineOptions& options = request.options;
    progress_->begin("loading and meshing", 0);
    // A saved solution is shown at once; its transport is rebuilt behind it, so stepping can continue.
    const bool saved = is_saved_solution_path(options.scene.scene);
    std::unique_ptr<RadiosityPipeline> pipeline;
    std::optional<PipelineOptions> saved_options;
    std::size_t saved_steps = 0;
    try {
        if (saved) {
            SavedSolution solution = read_saved_solution(options.scene.scene);
            saved_options = options_from_saved(solution.settings, options);
            saved_steps = solution.report.steps;
            pipeline = std::make_unique<RadiosityPipeline>(std::move(solution), options.scene.scene,
                                                           options.display);
        } else {
            pipeline = std::make_unique<RadiosityPipeline>(options);
        }
    } catch (const InputError& e) {
        // Nothing changed, so the previous scene stays shown, its steps go on, and the work this request
        // cut short starts again.
        std::lock_guard lock(mutex_);
        snapshot_.error = input_error_message(e);
        snapshot_.bad_input = true;
        if (interrupted_rebuild_ && !pending_rebuild_) {
            pending_rebuild_ = std::move(interrupted_rebuild_);
            keep_error_jobs_ =
                2;  // this job and the restarted one: that does not hide why the scene did not open
        }
        interrupted_rebuild_.reset();
        return;
    }
    {
        std::lock_guard lock(mutex_);
        interrupted_rebuild_.reset();
        if (pipeline_)
            running_ = false;  // the previous scene's run ends (a run asked for at the start waits)
        pending_steps_ += request.steps;
    }
    const std::string scene = saved_options ? saved_options->scene.scene : options.scene.scene;
    // The same scene again (another patch size, subdivision or form-factor method): its solution stays
    // shown until the new one has its transport, and a Cancel keeps it.
    if (!saved && pipeline_ && solver_ready_ && scene == shown_scene_) {
        pipeline->prepare(progress_.get());
        show_pipeline(std::move(pipeline), options, std::nullopt);
        display_ = pipeline_->build_display(options_.display, progress_.get());
        start_solver(Reset{options_.solver.method, options_.solver.tolerance, false}, true);
        return;
    }
    if (scene != shown_scene_ || !pipeline_) ++scene_version_;
    shown_scene_ = scene;
    show_pipeline(std::move(pipeline), options, std::move(saved_options));
    if (saved) {
        display_ = pipeline_->build_display(options_.display, progress_.get());
        publish(true, true);
        publish_statistics();
        pipeline_->prepare(progress_.get());
        solver_ready_ = true;
        continue_saved(saved_steps);
        return;
    }
    show_preview();
    pipeline_->prepare(progress_.get());
    solver_ready_ = true;
    // Built again from the patches: adaptive, hierarchical or clustered leaves are new geometry, and the
    // direct light splits the display's triangles along shadow edges, so it is traced on the unsplit mesh,
    // now with the patches' means kept.
    display_ = pipeline_->build_display(options_.display, progress_.get());
    start_solver(Reset{options_.solver.method, options_.solver.tolerance, false}, true);
}

void SolverWorker::show_pipeline(std::unique_ptr<RadiosityPipeline> pipeline, const PipelineOptions& options,
                                 std::optional<PipelineOptions> saved_options) {
    const DisplayOptions display = options_.display;
    const bool had_pipeline = pipeline_ != nullptr;
    options_ = options;
    if (had_pipeline) options_.display = display;  // a smooth/flat choice made since the start stays
    pipeline_ = std::move(pipeline);
    solver_ready_ = false;
    step_offset_ = 0;
    saved_options_ = std::move(saved_options);
    remesh_unavailable_ = saved_options_ ? missing_scene(saved_options_->scene.scene) : std::string();
    ++opened_;
    materials_ = scene_materials(pipeline_->loaded().scene);
    // The previous scene's plots and bounces are not this one's.
    start_bounce_history();
    history_residual_.clear();
    history_unshot_.clear();
    set_can_step(false);
    std::lock_guard lock(mutex_);
    if (keep_error_jobs_ > 0) return;
    snapshot_.error.clear();
    snapshot_.bad_input = false;
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
    pipeline_->add_preview_direct_light(display_);
    // New geometry: the direct light splits the triangles along shadow edges.
    if (!display_.direct.vertex.empty()) publish(true, true);
}

void SolverWorker::continue_saved(std::size_t saved_steps) {
    // The pipeline's solver continues from the saved radiosity; a reset would start it from the emission.
    // A saved solution's rebuilt elements were checked to be the saved ones, which are drawn already.
    step_offset_ = saved_steps;
    start_bounce_history();
    add_bounce(pipeline_->solver().display_solution(),
               direct_light_share(display_, pipeline_->solver().display_solution()));
    set_can_step(!pipeline_->solver().report().finished());
    publish(false, true);
}

void SolverWorker::reset_solver(const Reset& reset) {
    start_solver(reset, false);
}

void SolverWorker::start_solver(const Reset& reset, bool geometry_changed) {
    if (!pipeline_) return;
    pipeline_->prepare(progress_.get());
    solver_ready_ = true;
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

void SolverWorker::edit_material(const MaterialEdit& edit) {
    if (!pipeline_) return;
    pipeline_->prepare(progress_.get());
    solver_ready_ = true;
    pipeline_->edit_material(edit.name, edit.reflectance, edit.emitted_radiance);
    materials_ = scene_materials(pipeline_->loaded().scene);
    run_after_edit();
}

void SolverWorker::edit_outside_light(const std::pair<std::string, std::string>& sky_and_sun) {
    if (!pipeline_) return;
    pipeline_->prepare(progress_.get());
    solver_ready_ = true;
    pipeline_->edit_outside_light(sky_and_sun.first, sky_and_sun.second, progress_.get());
    options_.scene.sky = sky_and_sun.first;
    options_.scene.sun = sky_and_sun.second;
    run_after_edit();
}

void SolverWorker::run_after_edit() {
    // The emitters' direct light at the vertices, and a textured surface's emission, change with an edit.
    display_ = pipeline_->build_display(options_.display, progress_.get());
    start_history_from_solver();
    const bool can_step = !pipeline_->solver().report().finished();
    set_can_step(can_step);
    {
        std::lock_guard lock(mutex_);
        running_ = can_step;  // live: the light settles to the edit without being asked
        snapshot_.error.clear();
    }
    publish(true, true);
}

void SolverWorker::write(const Write& file) {
    if (!pipeline_) return;
    std::string error;
    try {
        if (is_saved_solution_path(file.path)) {
            if (!solver_ready_)
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
    // Before the transport is rebuilt: the saved state. While form factors run: the emission, and the
    // emitters' direct light at the vertices once it is traced.
    if (const SavedSolution* saved = pipeline_->saved()) return saved->display_solution;
    if (!solver_ready_) return pipeline_->preview_radiosity();
    return pipeline_->solver().display_solution();
}

std::optional<double> SolverWorker::shown_direct_share() const {
    if (!pipeline_->saved() && !solver_ready_) return 1.0;
    return std::nullopt;
}

void SolverWorker::take_step() {
    if (!pipeline_ || !solver_ready_) return;
    const std::vector<glm::dvec3> before = pipeline_->solver().display_solution();
    const StepReport report = pipeline_->step();
    const std::vector<glm::dvec3> after = pipeline_->solver().display_solution();
    previous_solution_ = before;
    add_bounce(positive_difference(after, before),
               direct_light_share(display_, after) - direct_light_share(display_, before));
    history_residual_.push_back(log10_or_floor(report.residual));
    history_unshot_.push_back(
        log10_or_floor(report.unshot_power.x + report.unshot_power.y + report.unshot_power.z));
    if (report.finished()) {
        std::lock_guard lock(mutex_);
        running_ = false;
        pending_steps_ = 0;
    }
    set_can_step(!report.finished());
    publish(false, true);
}

void SolverWorker::switch_colour_mode(ColourMode mode) {
    if (!pipeline_ || options_.display.mode == mode) return;
    options_.display.mode = mode;
    display_ = pipeline_->build_display(options_.display, progress_.get());
    for (std::size_t i = 0; i < bounce_history_.size(); ++i) {
        vertex_bounces_[i] = std::make_shared<const std::vector<glm::vec3>>(
            vertex_radiance(display_, bounce_history_[i], bounce_direct_share_[i], false));
    }
    publish(true, true);
}

void SolverWorker::start_history_from_solver() {
    step_offset_ = 0;
    start_bounce_history();
    // Step 0: the solver's first radiosity (the emission, or its first guess) is the newest light.
    add_bounce(pipeline_->solver().display_solution(),
               direct_light_share(display_, pipeline_->solver().display_solution()));
    history_residual_.clear();
    history_unshot_.clear();
}

void SolverWorker::start_bounce_history() {
    previous_solution_.clear();
    bounce_history_.clear();
    vertex_bounces_.clear();
    bounce_direct_share_.clear();
    first_bounce_ = 0;
}

void SolverWorker::add_bounce(std::vector<glm::dvec3> bounce, double direct_share) {
    vertex_bounces_.push_back(std::make_shared<const std::vector<glm::vec3>>(
        // One bounce's light alone is no solution to gather from: its patches show it.
        vertex_radiance(display_, bounce, direct_share, false)));
    bounce_history_.push_back(std::move(bounce));
    bounce_direct_share_.push_back(direct_share);
    if (bounce_history_.size() > kKeptBounces) {
        bounce_history_.pop_front();
        vertex_bounces_.pop_front();
        bounce_direct_share_.pop_front();
        ++first_bounce_;
    }
}

void SolverWorker::set_can_step(bool can_step) {
    std::lock_guard lock(mutex_);
    can_step_ =
        can_step;  // steps asked for before the solver exists wait for it (scripted runs rely on that)
}

void SolverWorker::publish(bool geometry_changed, bool with_radiance) {
    // Built before taking the lock, which the render thread takes every frame.
    std::shared_ptr<ViewerGeometry> geometry;
    if (geometry_changed) {
        geometry = std::make_shared<ViewerGeometry>();
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
    }
    std::shared_ptr<ViewerRadiance> radiance;
    if (with_radiance) {
        radiance = std::make_shared<ViewerRadiance>();
        const std::vector<glm::dvec3> shown = shown_radiosity();
        const bool stepped =
            solver_ready_ && !pipeline_->saved() && previous_solution_.size() == shown.size();
        radiance->cumulative = stepped ? stepped_vertex_radiance(display_, shown, previous_solution_)
                                       : vertex_radiance(display_, shown, shown_direct_share());
        if (const SavedSolution* saved = pipeline_->saved()) {
            // Before the transport is rebuilt: the saved state, with no bounce history.
            radiance->step = saved->report.steps;
        } else if (solver_ready_) {
            radiance->bounces.assign(vertex_bounces_.begin(), vertex_bounces_.end());
            radiance->first_bounce = step_offset_ + first_bounce_;
            radiance->step = step_offset_ + pipeline_->solver().report().step;
        }
    }
    {
        std::lock_guard lock(mutex_);
        if (geometry) snapshot_.geometry = std::move(geometry);
        snapshot_.radiance = std::move(radiance);
    }
    changed();
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
        statistics.prepared = solver_ready_;
        statistics.form_factor_passes = pipeline_->work().form_factor_passes;
        if (statistics.prepared) {
            const TransportReport transport = pipeline_->transport().report();
            statistics.interactions = transport.interactions;
            statistics.interaction_name = transport.interaction_name;
            statistics.status = pipeline_->solver().report().status;
            statistics.status_message = pipeline_->solver().status_message();
        }
        statistics.log_residual = history_residual_;
        statistics.log_unshot = history_unshot_;
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
    pending_steps_ = 0;
    running_ = false;
}

}  // namespace rad
