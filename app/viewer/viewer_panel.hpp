#pragma once

#include <cstdint>
#include <optional>
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
    bool copy_camera = false;
    bool show_help = false;
    bool add_bookmark = false;                  // keep the view as it is now
    std::optional<std::size_t> go_to_bookmark;  // ViewSettings::bookmarks' index
    // The width the panel takes at the window's left edge, in Dear ImGui's units (the window's, not its
    // framebuffer's); 0 while it is collapsed to its title bar. The 3D view is drawn beside it.
    float docked_width = 0.0f;
};

// The options a scene opened from the panel starts from: the panel's, at the scene's own default patch size
// and the default subdivision, since another scene is of another scale (a patch size of 20 suits the Cornell
// box's millimetres, not a unit cube).
PipelineOptions options_for_new_scene(PipelineOptions options, const std::string& path);

// The Dear ImGui panel, docked at the window's left edge over its whole height: solver and meshing controls
// (sent to the worker), view settings, the progress of running work with a cancel button, the residual plot
// and statistics. Call draw() between ImGui's NewFrame and Render.
class ViewerPanel {
  public:
    explicit ViewerPanel(const PipelineOptions& options);

    PanelRequests draw(SolverWorker& worker, ViewSettings& view, const FrameTimer& frames);
    // Loads another scene with the panel's patch size and form-factor method, or a saved solution
    // (FILE.radiosity) as it was saved (the panel's Open, or a drop).
    void open_scene(SolverWorker& worker, const std::string& path);
    // The material of a surface clicked in the view, shown for editing (its place in
    // ViewerStatistics::materials).
    void select_material(std::uint32_t index);
    // A line shown at the bottom of the panel (where a screenshot went, say).
    void set_message(const std::string& message) { message_ = message; }

  private:
    void show_options();        // the controls' choices from options_
    void use_scene_defaults();  // the scene's own patch size and the default subdivision
    // Loads the scene shown (or the one a saved solution came from) again with the panel's settings.
    void remesh(SolverWorker& worker, const ViewerStatistics& statistics);
    void draw_solver(SolverWorker& worker, const SolverSnapshot& snapshot);
    void draw_progress(SolverWorker& worker);
    void draw_plot(const ViewerStatistics& statistics);
    void draw_view(SolverWorker& worker, ViewSettings& view, PanelRequests& requests);
    void draw_bounce_choice(const SolverWorker& worker, ViewSettings& view);
    void draw_scene(SolverWorker& worker, const ViewerStatistics& statistics);
    void draw_statistics(const ViewerStatistics& statistics, const FrameTimer& frames);
    void draw_material(SolverWorker& worker, const ViewerStatistics& statistics);
    void draw_files(SolverWorker& worker, const ViewSettings& view, PanelRequests& requests);
    void write_cameras(const std::string& path, const std::vector<Camera>& cameras);

    PipelineOptions options_;  // the values the panel's controls edit
    int method_index_ = 0;
    int form_factor_index_ = 0;
    int subdivision_index_ = 0;  // the position in all_subdivisions()
    std::uint64_t opened_ = 0;   // the worker's ViewerStatistics::opened last seen
    std::string scene_path_;
    std::string save_stem_;  // what Save and Export write, without the extension
    // The material edited: its place in the statistics' list, and the values the controls show.
    int material_ = -1;
    bool material_loaded_ = false;  // the controls hold the material's values (not yet those of another)
    float reflectance_[3] = {0, 0, 0};
    float emission_colour_[3] = {0, 0, 0};     // Le over its largest channel
    float emission_strength_ = 0.0f;           // that largest channel
    const Progress* progress_seen_ = nullptr;  // the job whose stage started at stage_start_
    std::uint64_t stage_number_ = 0;
    double stage_start_ = 0.0;
    std::string message_;
};

}  // namespace rad
