#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
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
#include "rad/util/progress.hpp"
#include "viewer/solver_snapshot.hpp"

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
    struct Rebuild {
        PipelineOptions options;
        std::size_t steps = 0;  // asked for with it, taken once it has opened
    };
    struct Reset {
        std::string method;
        double tolerance;
        bool from_emission;  // B = E whatever --initial says (the panel's reset); else --initial's guess
    };

    struct MaterialEdit {
        std::string name;
        glm::dvec3 reflectance;
        glm::dvec3 emitted_radiance;
    };

    struct Write {
        std::string path;
        double exposure;
    };

    void loop();
    void edit_material(const MaterialEdit& edit);
    void edit_outside_light(const std::pair<std::string, std::string>& sky_and_sun);
    // After an edit of the transport's sources: the display again, a fresh history, and the run started.
    void run_after_edit();
    void write(const Write& write);
    bool has_work() const;  // with mutex_ held
    void rebuild(const Rebuild& request);
    // The newly loaded pipeline becomes the one shown; a new scene's is not prepared yet.
    void show_pipeline(std::unique_ptr<RadiosityPipeline> pipeline, const PipelineOptions& options,
                       std::optional<PipelineOptions> saved_options);
    void show_preview();
    void continue_saved(std::size_t saved_steps);
    void reset_solver(const Reset& reset);
    void start_solver(const Reset& reset, bool geometry_changed);
    void take_step();
    void switch_colour_mode(ColourMode mode);
    void set_can_step(bool can_step);
    void start_bounce_history();
    // A fresh history whose step 0 is the solver's radiosity as it starts, with no plots yet.
    void start_history_from_solver();
    // `direct_share`: how much of the emitters' direct light the step added (direct_light_share's rise).
    void add_bounce(std::vector<glm::dvec3> bounce, double direct_share);
    // Hands the display mesh (when it changed) and the colours (when the solver has some) to the render
    // thread.
    void publish(bool geometry_changed, bool with_radiance);
    void publish_statistics();
    // The radiosity drawn now (the saved, the preview's, or the solver's) and the direct share it is drawn
    // with.
    std::vector<glm::dvec3> shown_radiosity() const;
    std::optional<double> shown_direct_share() const;
    void fail(const std::string& message, bool bad_input = false);
    void changed();  // without mutex_ held

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    // Requests, guarded by mutex_.
    std::optional<Rebuild> pending_rebuild_;
    std::optional<Rebuild> current_rebuild_;      // the rebuild running now
    std::optional<Rebuild> interrupted_rebuild_;  // cut short by a newer one
    // Rebuilds, this one included, that keep the error shown: a failed load's, while the work it cut short
    // starts again.
    int keep_error_jobs_ = 0;
    std::optional<Reset> pending_reset_;
    std::optional<ColourMode> pending_colour_mode_;
    std::vector<MaterialEdit> pending_edits_;
    std::optional<std::pair<std::string, std::string>> pending_outside_;  // sky, sun
    std::vector<Write> pending_writes_;
    std::size_t pending_steps_ = 0;
    bool running_ = false;
    bool stop_ = false;
    bool working_ = false;
    bool can_step_ = false;  // a solver exists and has not finished
    std::shared_ptr<Progress> progress_;
    SolverSnapshot snapshot_;

    // The worker thread's own state.
    PipelineOptions options_;
    std::unique_ptr<RadiosityPipeline> pipeline_;
    DisplayMesh display_;
    // Per patch, what each of the last steps added (front: step first_bounce_), and the same per vertex.
    std::deque<std::vector<glm::dvec3>> bounce_history_;
    std::deque<ViewerRadiance::Colours> vertex_bounces_;
    std::deque<double> bounce_direct_share_;
    std::size_t first_bounce_ = 0;
    // The solver's radiosity one step before the one shown (empty at the start of a history), which the
    // vertices with a gather row take (stepped_vertex_radiance), so they show the bounces of the step too.
    std::vector<glm::dvec3> previous_solution_;
    std::vector<float> history_residual_;
    std::vector<float> history_unshot_;
    std::string scene_name_;
    std::string shown_scene_;  // the scene drawn (a saved solution's own), which keeps the view when reopened
    std::uint64_t scene_version_ = 0;
    std::uint64_t opened_ = 0;
    std::shared_ptr<const std::vector<ViewerMaterial>> materials_;  // the scene's, as shown
    std::optional<PipelineOptions> saved_options_;                  // see ViewerStatistics::saved_options
    std::string remesh_unavailable_;
    // A saved solution continues from its own step count (the pipeline's solver counts from 0 again).
    std::size_t step_offset_ = 0;
    // The pipeline has a solver: prepare() returned (it can throw after counting a form-factor pass).
    bool solver_ready_ = false;
    std::function<void()> on_change_;
    std::atomic<std::uint64_t> changes_{0};
    tbb::task_arena arena_;  // where the work's parallel stages run
    std::thread thread_;     // last, so it starts after everything it uses exists
};

}  // namespace rad
