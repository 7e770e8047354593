#include "viewer/viewer.hpp"

#include <glad/gl.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>

#include <sys/resource.h>

#include <imgui.h>

#include "rad/camera/camera_view.hpp"
#include "rad/display/auto_exposure.hpp"
#include "rad/io/image_file.hpp"
#include "text/camera_text.hpp"
#include "viewer/false_colour_legend.hpp"
#include "viewer/help_overlay.hpp"
#include "viewer/pick.hpp"
#include "viewer/window_screenshot.hpp"

namespace rad {

namespace {

// A tenth of the scene's size per second is slow for crossing it; a quarter crosses a room in a few seconds.
constexpr double kSpeedPerSceneSize = 0.25;
// With nothing to draw, the loop sleeps until an event, or this long (for --idle's end).
constexpr double kIdleWaitSeconds = 0.25;
// Frames drawn after the last input: Dear ImGui shows a click or a hover a frame or two later.
constexpr int kFramesAfterInput = 3;
// A stalled frame (the window dragged, the machine busy) moves the camera at most this long's worth, so the
// view does not jump through a wall when frames resume.
constexpr double kLongestMoveSeconds = 0.25;

// User and system time of the whole process: the render thread, the worker and the driver's threads.
double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

glm::dvec3 centre(const BoundingBox& box) {
    return box.empty() ? glm::dvec3(0.0) : 0.5 * (box.min + box.max);
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      window_(options.width, options.height, "radiosity"),
      imgui_(window_.handle()),
      panel_(options.pipeline),
      worker_(options.pipeline, [] { glfwPostEmptyEvent(); }) {
    view_.auto_exposure = options.exposure.automatic;
    view_.exposure = options.exposure.ev;
    view_.mode = options.pipeline.display.mode;
    // Without a script the view opens at the first bounce, the direct light, rather than at the emission.
    if (options.steps != 0)
        worker_.request_steps(options.steps > 0 ? static_cast<std::size_t>(options.steps) : 1);
}

int Viewer::run() {
    double last = glfwGetTime();
    while (!window_.should_close()) {
        Framebuffer framebuffer;
        glfwGetFramebufferSize(window_.handle(), &framebuffer.width, &framebuffer.height);
        const bool minimized = framebuffer.width == 0 || framebuffer.height == 0;
        const bool waited = minimized || !needs_frames();
        if (waited) {
            glfwWaitEventsTimeout(kIdleWaitSeconds);
        } else {
            glfwPollEvents();
        }
        if (glfwGetWindowAttrib(window_.handle(), GLFW_FOCUSED) != GLFW_TRUE) camera_input_.release();
        const double now = glfwGetTime();
        const double seconds = now - last;
        last = now;
        advance_idle();
        // Woken by the timeout with nothing new: nothing is drawn.
        if (minimized || (waited && !needs_frames())) continue;
        // A frame after a sleep would count the sleep as its own duration.
        if (!waited) frames_.add(seconds, worker_.busy());
        frame(framebuffer, waited ? 0.0 : std::min(seconds, kLongestMoveSeconds));
    }
    return exit_status_;
}

bool Viewer::needs_frames() {
    if (window_.event_count() != seen_events_) {
        seen_events_ = window_.event_count();
        frames_owed_ = kFramesAfterInput;
    }
    const bool scripted = options_.steps >= 0 && !script_done_;
    return scripted || worker_.busy() || worker_.changes() != drawn_changes_ || frames_owed_ > 0 ||
           camera_input_.moving(window_.handle());
}

void Viewer::frame(const Framebuffer& framebuffer, double seconds) {
    ++frames_drawn_;
    frames_owed_ = std::max(frames_owed_ - 1, 0);
    drawn_changes_ = worker_.changes();  // read before the snapshot: a change in between is drawn next time
    const bool worker_busy = worker_.busy();
    const SolverSnapshot snapshot = worker_.snapshot();
    take_worker_results(snapshot);

    imgui_.begin_frame();
    PanelRequests requests = panel_.draw(worker_, view_, frames_);
    const WindowEvents events = window_.take_events();
    handle_window_events(events, requests);
    if (camera_ && geometry_) {
        camera_input_.orbit = view_.orbit;
        const bool keyboard = !imgui_.wants_keyboard() && glfwGetWindowAttrib(window_.handle(), GLFW_FOCUSED);
        camera_input_.update(window_.handle(), *camera_, centre(geometry_->bounds), seconds, keyboard,
                             !imgui_.wants_mouse());
    }
    if (requests.reset_view && camera_) camera_->reset();
    if (requests.add_bookmark && camera_) view_.bookmarks.push_back(camera_->camera());
    if (requests.go_to_bookmark) go_to_bookmark(*requests.go_to_bookmark);

    const ViewRect view = view_rect(framebuffer, requests.docked_width);
    if (!imgui_.wants_mouse()) {
        for (const glm::dvec2& click : events.clicks) pick(click, view);
    }
    if (requests.show_help) show_help_ = true;
    const ImVec2 window = ImGui::GetIO().DisplaySize;
    draw_help_overlay(show_help_, 0.5f * (requests.docked_width + window.x), 0.5f * window.y);
    if (requests.copy_camera) copy_camera();
    if (view_.false_colour && geometry_)
        draw_false_colour_legend(false_colour_scale_shown(), window.x - 10.0f, 10.0f);
    draw_scene(framebuffer, view);
    if (requests.screenshot) {
        if (const auto written = save_screenshot(timestamped_screenshot_path(), view)) {
            panel_.set_message("screenshot: " + *written);
        }
    }
    advance_script(snapshot, worker_busy, view);
    imgui_.end_frame();
    window_.swap_buffers();
    if (events.first_press) frames_.add_input_latency(glfwGetTime() - *events.first_press, worker_busy);
}

void Viewer::take_worker_results(const SolverSnapshot& snapshot) {
    bool new_geometry = false;
    if (snapshot.geometry && snapshot.geometry != geometry_) {
        const ViewerGeometry& geometry = *snapshot.geometry;
        renderer_.upload_geometry(geometry.positions, geometry.triangles, geometry.outline);
        renderer_.upload_textures(geometry.texcoords, geometry.textured);
        geometry_ = snapshot.geometry;
        new_geometry = true;
        if (!camera_ || geometry.scene_version != scene_version_) {
            const double size = geometry.bounds.empty() ? 1.0 : glm::length(geometry.bounds.extent());
            camera_.emplace(geometry.scene_camera, kSpeedPerSceneSize * size);
            scene_version_ = geometry.scene_version;
        }
    }
    radiance_ = snapshot.radiance;
    if (!geometry_) return;
    const ViewerRadiance::Colours colours = colours_to_show();
    if (!new_geometry && colours == shown_colours_) return;
    // Holding what was uploaded keeps its address from being reused by newer colours.
    shown_colours_ = colours;
    if (colours && colours->size() == geometry_->positions.size()) {
        renderer_.update_colours(*colours);
    } else {
        renderer_.update_colours(std::vector<glm::vec3>(geometry_->positions.size(), glm::vec3(0.0f)));
    }
}

ViewerRadiance::Colours Viewer::colours_to_show() const {
    if (!radiance_) return nullptr;
    if (!view_.bounce_only) return ViewerRadiance::Colours(radiance_, &radiance_->cumulative);
    return radiance_->bounce(view_.newest_bounce ? radiance_->step : view_.bounce);
}

void Viewer::handle_window_events(const WindowEvents& events, PanelRequests& requests) {
    if (camera_ && !imgui_.wants_mouse() && events.scroll != 0.0) camera_->scroll_speed(events.scroll);
    if (!events.dropped.empty()) panel_.open_scene(worker_, events.dropped.front());
    if (imgui_.wants_keyboard()) return;
    for (const int key : events.pressed_keys) {
        switch (key) {
            case GLFW_KEY_F12:
            case GLFW_KEY_P:
                requests.screenshot = true;
                break;
            case GLFW_KEY_R:
                requests.reset_view = true;
                break;
            case GLFW_KEY_TAB:
            case GLFW_KEY_O:
                view_.orbit = !view_.orbit;
                break;
            case GLFW_KEY_N:
                worker_.request_steps(1);
                break;
            case GLFW_KEY_SPACE:
                worker_.set_running(!worker_.running());
                break;
            case GLFW_KEY_B:
                view_.bounce_only = !view_.bounce_only;
                break;
            case GLFW_KEY_C:
                requests.copy_camera = true;
                break;
            case GLFW_KEY_F1:
                show_help_ = !show_help_;
                break;
            case GLFW_KEY_K:
                requests.add_bookmark = true;
                break;
            case GLFW_KEY_ESCAPE:
                window_.request_close();
                break;
            default:
                if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9)
                    requests.go_to_bookmark = static_cast<std::size_t>(key - GLFW_KEY_1);
                break;
        }
    }
}

Viewer::ViewRect Viewer::view_rect(const Framebuffer& framebuffer, float docked_width) const {
    // Dear ImGui counts in window units; the framebuffer may have more pixels (a HiDPI screen).
    const float window_width = ImGui::GetIO().DisplaySize.x;
    const int panel =
        window_width > 0.0f
            ? static_cast<int>(std::lround(docked_width * float(framebuffer.width) / window_width))
            : 0;
    const int x = std::clamp(panel, 0, std::max(framebuffer.width - 1, 0));
    return ViewRect{x, framebuffer.width - x, framebuffer.height};
}

void Viewer::draw_scene(const Framebuffer& framebuffer, const ViewRect& view) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebuffer.width, framebuffer.height);
    // The shader writes the sRGB code of L · 2^exposure, as PNGs hold, whatever the window's framebuffer.
    glDisable(GL_FRAMEBUFFER_SRGB);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!camera_ || !geometry_) return;
    glViewport(view.x, 0, view.width, view.height);
    const glm::mat4 projection = view_projection_of(view);
    if (view_.auto_exposure) meter_exposure(projection, view);
    DrawOptions draw;
    draw.exposure_scale = static_cast<float>(std::exp2(view_.exposure));
    draw.encode_srgb = true;
    draw.outline = view_.outline;
    if (view_.false_colour) draw.false_colour = false_colour_scale_shown();
    renderer_.draw(projection, draw);
}

FalseColourScale Viewer::false_colour_scale_shown() const {
    // The exposure maps the view's log-average luminance Y to the key, 0.18: Y = 0.18 / 2^exposure.
    const double mean = kLuminousEfficacy * kAutoExposureKey * std::exp2(-view_.exposure);
    return false_colour_scale(mean, view_.false_colour_decades);
}

glm::mat4 Viewer::view_projection_of(const ViewRect& view) const {
    const double aspect = double(view.width) / double(std::max(view.height, 1));
    return view_projection(camera_->camera(), aspect, geometry_->bounds);
}

void Viewer::pick(const glm::dvec2& window_point, const ViewRect& view) {
    if (!camera_ || !geometry_ || view.width <= 0 || view.height <= 0) return;
    // Window units to framebuffer pixels (a HiDPI screen has more of them), then to the view's [-1, 1]².
    const ImVec2 window = ImGui::GetIO().DisplaySize;
    if (window.x <= 0.0f || window.y <= 0.0f) return;
    const double x = window_point.x * (view.x + view.width) / window.x - view.x;
    const double y = window_point.y * view.height / window.y;
    const glm::dvec2 ndc(2.0 * x / view.width - 1.0, 1.0 - 2.0 * y / view.height);
    if (std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0) return;
    const auto triangle =
        pick_triangle(geometry_->positions, geometry_->triangles, pick_ray(view_projection_of(view), ndc));
    if (!triangle || *triangle >= geometry_->triangle_material.size()) return;
    panel_.select_material(geometry_->triangle_material[*triangle]);
}

// The meter's image: small, as the geometric mean needs no detail; the window's projection stretched to it
// shows the same scene.
constexpr int kMeterSide = 64;

void Viewer::meter_exposure(const glm::mat4& view_projection, const ViewRect& view) {
    // The emission alone (before the first bounce, while form factors compute) would meter the lights
    // themselves to grey: the exposure stays as it was until reflected light is shown.
    if (!radiance_) return;
    const std::size_t shown = view_.bounce_only && !view_.newest_bounce ? view_.bounce : radiance_->step;
    if (shown == 0) return;
    if (meter_ && view_projection == metered_view_ && renderer_.colour_uploads() == metered_colours_) return;
    if (!meter_) meter_ = std::make_unique<OffscreenTarget>(kMeterSide, kMeterSide, 1, PixelFormat::radiance);
    meter_->bind();
    renderer_.draw(view_projection, DrawOptions{});
    const double metered = auto_exposure(Image{kMeterSide, kMeterSide, meter_->read_pixels()});
    // The panel, drawn before the meter this frame, shows the new value in the next.
    if (metered != view_.exposure) frames_owed_ = std::max(frames_owed_, 1);
    view_.exposure = metered;
    metered_view_ = view_projection;
    metered_colours_ = renderer_.colour_uploads();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(view.x, 0, view.width, view.height);
}

void Viewer::go_to_bookmark(std::size_t index) {
    if (!camera_ || index >= view_.bookmarks.size()) return;
    camera_->go_to(view_.bookmarks[index]);
}

void Viewer::copy_camera() {
    if (!camera_) return;
    const std::string text = camera_option_text(camera_->camera());
    glfwSetClipboardString(window_.handle(), text.c_str());
    std::printf("camera: %s\n", text.c_str());
    std::fflush(stdout);
    panel_.set_message("copied: " + text);
}

std::optional<std::string> Viewer::save_screenshot(const std::string& path, const ViewRect& view) {
    try {
        // The 3D view alone, without the panel beside it.
        write_image(path, read_window_image(view.width, view.height, view.x), 0.0);
    } catch (const std::exception& e) {
        std::cerr << "radiosity: error: screenshot " << path << ": " << e.what() << '\n';
        panel_.set_message(std::string("screenshot failed: ") + e.what());
        return std::nullopt;
    }
    std::printf("wrote %s (%dx%d)\n", path.c_str(), view.width, view.height);
    std::fflush(stdout);
    return path;
}

void Viewer::advance_script(const SolverSnapshot& snapshot, bool worker_busy, const ViewRect& view) {
    if (options_.steps < 0 || script_done_ || worker_busy) return;
    if (!snapshot.error.empty()) {
        std::cerr << "radiosity: error: " << snapshot.error << '\n';
        exit_status_ = snapshot.bad_input ? 2 : 1;
        script_done_ = true;
        window_.request_close();
        return;
    }
    if (!radiance_ || !geometry_) return;  // not yet loaded (the worker is between jobs)
    script_done_ = true;
    if (radiance_->step < static_cast<std::size_t>(options_.steps)) {
        std::printf("the solver finished after %zu of the %d steps asked for\n", radiance_->step,
                    options_.steps);
    }
    std::printf(
        "step %zu; frames: %zu, mean %.1f ms, longest %.1f ms, longest while working after the first %zu "
        "%.1f ms\n",
        radiance_->step, frames_.count(), frames_.mean() * 1e3, frames_.longest() * 1e3,
        FrameTimer::kWarmUpFrames, frames_.longest_while_busy() * 1e3);
    if (frames_.inputs() > 0) {
        std::printf("input to screen: %zu presses, longest %.1f ms, longest while working %.1f ms\n",
                    frames_.inputs(), frames_.longest_input_latency() * 1e3,
                    frames_.longest_input_latency_while_busy() * 1e3);
    }
    if (!options_.screenshot.empty() && !save_screenshot(options_.screenshot, view)) exit_status_ = 1;
    if (options_.idle_seconds > 0.0) {
        idle_ = IdleStart{glfwGetTime(), process_cpu_seconds(), frames_drawn_};
    } else if (options_.exit) {
        window_.request_close();
    }
}

void Viewer::advance_idle() {
    if (!idle_ || glfwGetTime() - idle_->time < options_.idle_seconds) return;
    const double seconds = glfwGetTime() - idle_->time;
    const double cpu = process_cpu_seconds() - idle_->cpu_seconds;
    std::printf("idle %.1f s: %zu frames drawn, %.3f s of CPU (%.1f %% of a core)\n", seconds,
                frames_drawn_ - idle_->frames, cpu, 100.0 * cpu / seconds);
    std::fflush(stdout);
    idle_.reset();
    if (options_.exit) window_.request_close();
}

}  // namespace rad
