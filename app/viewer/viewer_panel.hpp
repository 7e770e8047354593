#pragma once

#include <cstdint>
#include <string>

#include "pipeline/radiosity_pipeline.hpp"
#include "viewer/frame_timer.hpp"
#include "viewer/solver_worker.hpp"
#include "viewer/view_settings.hpp"

namespace rad {

// What the panel asks the viewer for, beyond what it sends the worker itself.
struct PanelRequests {
    bool screenshot = false;
    bool reset_view = false;
};

// The Dear ImGui panel: solver and meshing controls (sent to the worker), view settings, the progress of
// running work with a cancel button, the residual plot and statistics. Call draw() between ImGui's NewFrame
// and Render.
class ViewerPanel {
  public:
    explicit ViewerPanel(const PipelineOptions& options);

    PanelRequests draw(SolverWorker& worker, ViewSettings& view, const FrameTimer& frames);
    // Loads another scene with the panel's patch size and form-factor method, or a saved solution
    // (FILE.radiosity) as it was saved (the panel's Open, or a drop).
    void open_scene(SolverWorker& worker, const std::string& path);
    // A line shown at the bottom of the panel (where a screenshot went, say).
    void set_message(const std::string& message) { message_ = message; }

  private:
    void show_options();  // the controls' choices from options_
    void draw_solver(SolverWorker& worker, const SolverSnapshot& snapshot);
    void draw_progress(SolverWorker& worker);
    void draw_plot(const ViewerStatistics& statistics);
    void draw_view(SolverWorker& worker, ViewSettings& view, PanelRequests& requests);
    void draw_bounce_choice(const SolverWorker& worker, ViewSettings& view);
    void draw_scene(SolverWorker& worker, const ViewerStatistics& statistics);
    void draw_statistics(const ViewerStatistics& statistics, const FrameTimer& frames);

    PipelineOptions options_;  // the values the panel's controls edit
    int method_index_ = 0;
    int form_factor_index_ = 0;
    int subdivision_index_ = 0;  // the position in all_subdivisions()
    std::uint64_t opened_ = 0;   // the worker's ViewerStatistics::opened last seen
    std::string scene_path_;
    std::string message_;
};

}  // namespace rad
