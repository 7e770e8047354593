#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <tbb/task_arena.h>

#include "pipeline/radiosity_pipeline.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/util/error.hpp"
#include "rad/util/progress.hpp"
#include "viewer/bounce_history.hpp"
#include "viewer/solver_snapshot.hpp"
#include "viewer/worker_commands.hpp"

namespace rad {

// Runs the long work of the viewer (loading and meshing, form factors, solver steps) on its own thread, so
// the render thread never waits for it. The render thread asks for work with the request functions, which
// return at once, and reads results with snapshot(). Cancelling stops form factors through
// Progress::cancel() and drops the steps not yet taken; the destructor cancels and joins.
class SolverWorker {
  public:
    // Starts the thread, which loads `options`' scene and computes its form factors. `on_change` is called on
    // the worker's thread after each new snapshot and at the end of each job (the viewer wakes its event
    // loop with it).
    explicit SolverWorker(const PipelineOptions& options, std::function<void()> on_change = {});
    ~SolverWorker();
    SolverWorker(const SolverWorker&) = delete;
    SolverWorker& operator=(const SolverWorker&) = delete;

    // Loads (another scene, or the same at another patch size or form-factor method) and recomputes; once the
    // scene has opened, takes `steps` solver steps (a file that does not open takes none from the scene
    // shown).
    void request_rebuild(const PipelineOptions& options, std::size_t steps = 0);
    void request_steps(std::size_t count);
    // Steps until the solver finishes, or until paused.
    void set_running(bool running);
    // A fresh solver from B = E (emission only) with this method and tolerance; keeps the form factors.
    void request_reset(const std::string& method, double tolerance);
    void request_colour_mode(ColourMode mode);
    // Gives the named material this reflectance and emitted radiance Le and runs the solver on from the
    // solution shown, with the same form factors. Edits of a material not yet made replace each other.
    void request_material_edit(const std::string& name, const glm::dvec3& reflectance,
                               const glm::dvec3& emitted_radiance);
    // The sky and sun as --sky and --sun take them (empty: as the scene was opened), measured again on the
    // same form factors; the solver runs on from the solution shown.
    void request_outside_light(const std::string& sky, const std::string& sun);
    // Writes the solution shown: FILE.radiosity (the solve-once format, after the form factors), or the
    // display mesh with its colours at this exposure (.ply, .gltf, .glb). The panel shows "wrote FILE", or
    // the error.
    void request_write(const std::string& path, double exposure);
    // Stops what runs now (form factors, a run of steps) and drops the steps asked for and not yet taken.
    void cancel();

    SolverSnapshot snapshot() const;
    // The stage and fraction of the work running now, when there is some.
    std::shared_ptr<const Progress> progress() const;
    bool busy() const;
    // Counts the snapshots published and the jobs ended: what the render thread has not drawn yet differs.
    std::uint64_t changes() const { return changes_.load(); }
    bool running() const;
    // Steps asked for and not yet taken.
    std::size_t pending_steps() const;

  private:
    using Command = WorkerCommands::Command;

    // Changes what is asked of the worker, under mutex_, and wakes it.
    void ask(const std::function<void()>& change);
    void loop();
    // Waits for the next command and takes it; nothing once the worker stops.
    std::optional<Command> wait_for_command();
    // Runs it on the work's threads; false when it failed (its error is shown).
    bool run(const Command& command);
    void end_job(const Command& command, bool completed);

    void rebuild(const WorkerCommands::Rebuild& request);
    // The scene or saved solution `options` names, loaded and meshed; throws InputError when it does not
    // open.
    struct OpenedScene {
        std::unique_ptr<RadiosityPipeline> pipeline;
        std::optional<PipelineOptions> saved_options;  // a saved solution's own
        std::size_t saved_steps = 0;
    };
    OpenedScene open_scene(const PipelineOptions& options) const;
    // Nothing changed, so the previous scene stays shown, its steps go on, and the work this request cut
    // short starts again.
    void not_opened(const InputError& error);
    // The newly loaded pipeline becomes the one shown; a new scene's is not prepared yet.
    void show_pipeline(std::unique_ptr<RadiosityPipeline> pipeline, const PipelineOptions& options,
                       std::optional<PipelineOptions> saved_options);
    void show_saved(std::size_t saved_steps);
    void show_preview();
    void start_solver(const WorkerCommands::Reset& reset, bool geometry_changed);
    void take_step();
    void switch_colour_mode(ColourMode mode);
    void edit_material(const WorkerCommands::MaterialEdit& edit);
    void edit_outside_light(const WorkerCommands::OutsideLight& light);
    // After an edit of the transport's sources: the display again, a fresh history, and the run started.
    void run_after_edit();
    void write(const WorkerCommands::Write& file);
    void prepare_solver();
    // A fresh history whose step 0 is the solver's radiosity as it starts, with no plots yet.
    void start_history_from_solver();
    void set_can_step(bool can_step);
    // Hands the display mesh (when it changed) and the colours (when the solver has some) to the render
    // thread.
    void publish(bool geometry_changed, bool with_radiance);
    std::shared_ptr<ViewerGeometry> shown_geometry() const;
    std::shared_ptr<ViewerRadiance> shown_radiance() const;
    void publish_statistics();
    // The radiosity drawn now (the saved, the preview's, or the solver's) and the direct share it is drawn
    // with.
    std::vector<glm::dvec3> shown_radiosity() const;
    std::optional<double> shown_direct_share() const;
    void fail(const std::string& message, bool bad_input = false);
    void changed();  // without mutex_ held

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    // Guarded by mutex_.
    WorkerCommands commands_;
    // Rebuilds, this one included, that keep the error shown: a failed load's, while the work it cut short
    // starts again.
    int keep_error_jobs_ = 0;
    bool stop_ = false;
    bool working_ = false;
    std::shared_ptr<Progress> progress_;
    SolverSnapshot snapshot_;

    // The worker thread's own state.
    PipelineOptions options_;
    std::unique_ptr<RadiosityPipeline> pipeline_;
    DisplayMesh display_;
    BounceHistory history_;
    std::string shown_scene_;  // the scene drawn (a saved solution's own), which keeps the view when reopened
    std::uint64_t scene_version_ = 0;
    std::uint64_t opened_ = 0;
    std::shared_ptr<const std::vector<ViewerMaterial>> materials_;  // the scene's, as shown
    std::optional<PipelineOptions> saved_options_;                  // see ViewerStatistics::saved_options
    std::string remesh_unavailable_;
    std::function<void()> on_change_;
    std::atomic<std::uint64_t> changes_{0};
    tbb::task_arena arena_;  // where the work's parallel stages run
    std::thread thread_;     // last, so it starts after everything it uses exists
};

}  // namespace rad
