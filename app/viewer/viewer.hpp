#pragma once

#include <memory>
#include <optional>
#include <string>

#include "gl/offscreen_target.hpp"
#include "gl/renderer.hpp"
#include "rad/camera/fly_camera.hpp"
#include "viewer/camera_input.hpp"
#include "viewer/frame_timer.hpp"
#include "viewer/glfw_window.hpp"
#include "viewer/imgui_layer.hpp"
#include "viewer/solver_worker.hpp"
#include "viewer/view_settings.hpp"
#include "viewer/viewer_options.hpp"
#include "viewer/viewer_panel.hpp"

namespace rad {

// The interactive viewer: one window, the renderer and the panel on this (the render) thread, the long work
// on a SolverWorker. Each frame reads the worker's latest results and uploads only what changed.
class Viewer {
  public:
    // Opens the window and starts loading the scene. Throws std::runtime_error when no window can be opened.
    explicit Viewer(const ViewerOptions& options);

    // Runs until the window closes (or the script ends); returns the exit status.
    int run();

  private:
    struct Framebuffer {
        int width = 0;
        int height = 0;
    };
    // The part of the framebuffer the 3D view takes, beside the docked panel, in framebuffer pixels.
    struct ViewRect {
        int x = 0;
        int width = 0;
        int height = 0;
    };

    // Something to draw: the script, the worker's work or results not yet drawn, input just now, a camera
    // moving. Otherwise the loop sleeps until an event.
    bool needs_frames();
    void frame(const Framebuffer& framebuffer, double seconds);
    void take_worker_results(const SolverSnapshot& snapshot);
    // The cumulative solution, or the chosen bounce alone; nullptr (black) when there is none.
    ViewerRadiance::Colours colours_to_show() const;
    void handle_window_events(const WindowEvents& events, PanelRequests& requests);
    glm::mat4 view_projection_of(const ViewRect& view) const;
    // Around the view's log-average luminance, which the exposure holds (metered, or as set).
    FalseColourScale false_colour_scale_shown() const;
    ViewRect view_rect(const Framebuffer& framebuffer, float docked_width) const;
    void draw_scene(const Framebuffer& framebuffer, const ViewRect& view);
    // Auto exposure: the view drawn small in radiance and metered (auto_exposure), again whenever the view
    // or the colours change; leaves the window's framebuffer bound.
    void meter_exposure(const glm::mat4& view_projection, const ViewRect& view);
    std::optional<std::string> save_screenshot(const std::string& path, const ViewRect& view);
    // A click in the view picks the material of the surface under it for the panel.
    void pick(const glm::dvec2& window_point, const ViewRect& view);
    void go_to_bookmark(std::size_t index);
    // The camera as `render` takes it, to the clipboard, stdout and the panel.
    void copy_camera();
    // Scripted runs: once the worker has taken the steps asked for, writes the screenshot and ends.
    void advance_script(const SolverSnapshot& snapshot, bool worker_busy, const ViewRect& view);
    // After the script, --idle: the frames and CPU seconds of the idle time, then --exit.
    void advance_idle();

    ViewerOptions options_;
    GlfwWindow window_;  // first: the OpenGL context everything below needs
    ImGuiLayer imgui_;
    Renderer renderer_;
    ViewerPanel panel_;
    CameraInput camera_input_;
    ViewSettings view_;
    FrameTimer frames_;
    std::optional<FlyCamera> camera_;
    std::shared_ptr<const ViewerGeometry> geometry_;  // what the renderer holds
    std::shared_ptr<const ViewerRadiance> radiance_;
    ViewerRadiance::Colours shown_colours_;  // what the renderer's colour buffer holds
    std::uint64_t scene_version_ = 0;
    std::unique_ptr<OffscreenTarget> meter_;
    glm::mat4 metered_view_{0.0f};
    std::size_t metered_colours_ = 0;  // the renderer's colour uploads when last metered
    int exit_status_ = 0;
    bool script_done_ = false;
    bool show_help_ = false;                           // the F1 overlay
    std::uint64_t drawn_changes_ = ~std::uint64_t(0);  // the worker's changes() when last drawn
    std::uint64_t seen_events_ = 0;                    // the window's event_count() when last looked at
    int frames_owed_ = 0;                              // frames still to draw after input
    std::size_t frames_drawn_ = 0;
    struct IdleStart {
        double time = 0.0;
        double cpu_seconds = 0.0;
        std::size_t frames = 0;
    };
    std::optional<IdleStart> idle_;  // --idle, once the script is done
    SolverWorker worker_;            // last: its thread stops and joins before the context goes
};

}  // namespace rad
