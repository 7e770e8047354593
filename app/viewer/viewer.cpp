#include "viewer/viewer.hpp"

#include <glad/gl.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>

#include "rad/camera/camera_view.hpp"
#include "rad/display/auto_exposure.hpp"
#include "rad/io/image_file.hpp"
#include "viewer/window_screenshot.hpp"

namespace rad {

namespace {

// A tenth of the scene's size per second is slow for crossing it; a quarter crosses a room in a few seconds.
constexpr double kSpeedPerSceneSize = 0.25;
// With nothing to show changing and no focus, the loop sleeps this long between looks at the events.
constexpr double kIdleWaitSeconds = 0.25;
// A stalled frame (the window dragged, the machine busy) moves the camera at most this long's worth, so the
// view does not jump through a wall when frames resume.
constexpr double kLongestMoveSeconds = 0.25;

glm::dvec3 centre(const BoundingBox& box) {
    return box.empty() ? glm::dvec3(0.0) : 0.5 * (box.min + box.max);
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options)
    : options_(options),
      window_(options.width, options.height, "radiosity"),
      imgui_(window_.handle()),
      panel_(options.pipeline),
      worker_(options.pipeline) {
    view_.auto_exposure = options.exposure.automatic;
    view_.exposure = options.exposure.ev;
    view_.mode = options.pipeline.display.mode;
    if (options.steps > 0) worker_.request_steps(static_cast<std::size_t>(options.steps));
}

int Viewer::run() {
    double last = glfwGetTime();
    while (!window_.should_close()) {
        const bool focused = glfwGetWindowAttrib(window_.handle(), GLFW_FOCUSED) == GLFW_TRUE;
        Framebuffer framebuffer;
        glfwGetFramebufferSize(window_.handle(), &framebuffer.width, &framebuffer.height);
        const bool minimized = framebuffer.width == 0 || framebuffer.height == 0;
        const bool scripted = options_.steps >= 0 && !script_done_;
        // Minimized, or in the background with no work to watch: sleep until something happens.
        const bool waited = minimized || (!scripted && !focused && !worker_.busy());
        if (waited) {
            glfwWaitEventsTimeout(kIdleWaitSeconds);
        } else {
            glfwPollEvents();
        }
        if (!focused) camera_input_.release();
        const double now = glfwGetTime();
        const double seconds = now - last;
        last = now;
        if (minimized) continue;
        // A frame after a sleep would count the sleep as its own duration.
        if (!waited) frames_.add(seconds, worker_.busy());
        frame(framebuffer, waited ? 0.0 : std::min(seconds, kLongestMoveSeconds));
    }
    return exit_status_;
}

void Viewer::frame(const Framebuffer& framebuffer, double seconds) {
    const bool worker_busy = worker_.busy();
    const SolverSnapshot snapshot = worker_.snapshot();
    take_worker_results(snapshot);

    imgui_.begin_frame();
    PanelRequests requests = panel_.draw(worker_, view_, frames_);
    handle_window_events(window_.take_events(), requests);
    if (camera_ && geometry_) {
        camera_input_.orbit = view_.orbit;
        const bool keyboard = !imgui_.wants_keyboard() && glfwGetWindowAttrib(window_.handle(), GLFW_FOCUSED);
        camera_input_.update(window_.handle(), *camera_, centre(geometry_->bounds), seconds, keyboard,
                             !imgui_.wants_mouse());
    }
    if (requests.reset_view && camera_) camera_->reset();

    draw_scene(framebuffer);
    if (requests.screenshot) {
        if (const auto written = save_screenshot(timestamped_screenshot_path(), framebuffer)) {
            panel_.set_message("screenshot: " + *written);
        }
    }
    advance_script(snapshot, worker_busy, framebuffer);
    imgui_.end_frame();
    window_.swap_buffers();
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
            case GLFW_KEY_ESCAPE:
                window_.request_close();
                break;
            default:
                break;
        }
    }
}

void Viewer::draw_scene(const Framebuffer& framebuffer) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, framebuffer.width, framebuffer.height);
    // The shader writes the sRGB code of L · 2^exposure, as PNGs hold, whatever the window's framebuffer.
    glDisable(GL_FRAMEBUFFER_SRGB);
    if (!camera_ || !geometry_) {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    const double aspect = double(framebuffer.width) / double(framebuffer.height);
    const glm::mat4 projection = view_projection(camera_->camera(), aspect, geometry_->bounds);
    if (view_.auto_exposure) meter_exposure(projection, framebuffer);
    DrawOptions draw;
    draw.exposure_scale = static_cast<float>(std::exp2(view_.exposure));
    draw.encode_srgb = true;
    draw.outline = view_.outline;
    renderer_.draw(projection, draw);
}

// The meter's image: small, as the geometric mean needs no detail; the window's projection stretched to it
// shows the same scene.
constexpr int kMeterSide = 64;

void Viewer::meter_exposure(const glm::mat4& view_projection, const Framebuffer& window) {
    // The emission alone (before the first bounce, while form factors compute) would meter the lights
    // themselves to grey: the exposure stays as it was until reflected light is shown.
    if (!radiance_) return;
    const std::size_t shown = view_.bounce_only && !view_.newest_bounce ? view_.bounce : radiance_->step;
    if (shown == 0) return;
    if (meter_ && view_projection == metered_view_ && renderer_.colour_uploads() == metered_colours_) return;
    if (!meter_) meter_ = std::make_unique<OffscreenTarget>(kMeterSide, kMeterSide, 1, PixelFormat::radiance);
    meter_->bind();
    renderer_.draw(view_projection, DrawOptions{});
    view_.exposure = auto_exposure(Image{kMeterSide, kMeterSide, meter_->read_pixels()});
    metered_view_ = view_projection;
    metered_colours_ = renderer_.colour_uploads();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window.width, window.height);
}

std::optional<std::string> Viewer::save_screenshot(const std::string& path, const Framebuffer& framebuffer) {
    try {
        write_image(path, read_window_image(framebuffer.width, framebuffer.height), 0.0);
    } catch (const std::exception& e) {
        std::cerr << "radiosity: error: screenshot " << path << ": " << e.what() << '\n';
        panel_.set_message(std::string("screenshot failed: ") + e.what());
        return std::nullopt;
    }
    std::printf("wrote %s (%dx%d)\n", path.c_str(), framebuffer.width, framebuffer.height);
    std::fflush(stdout);
    return path;
}

void Viewer::advance_script(const SolverSnapshot& snapshot, bool worker_busy,
                            const Framebuffer& framebuffer) {
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
    if (!options_.screenshot.empty() && !save_screenshot(options_.screenshot, framebuffer)) exit_status_ = 1;
    if (options_.exit) window_.request_close();
}

}  // namespace rad
