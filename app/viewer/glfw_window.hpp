#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>

#include <string>
#include <vector>

struct GLFWwindow;

namespace rad {

// What happened to the window since the last take_events(): collected by GLFW's callbacks, which Dear ImGui
// chains after its own.
struct WindowEvents {
    double scroll = 0.0;               // wheel steps, up positive
    std::vector<int> pressed_keys;     // GLFW key codes, in order
    std::vector<std::string> dropped;  // paths of files dropped on the window
    std::vector<glm::dvec2> clicks;    // where the left button went down, in window coordinates
    // glfwGetTime() when the first key or button of these went down (input waiting to reach the screen).
    std::optional<double> first_press;
};

// The platform side of the viewer: GLFW, one window with an OpenGL 3.3 core context made current on the
// calling thread, asked for an sRGB-capable framebuffer so it shows what `render` PNGs hold.
class GlfwWindow {
  public:
    // Throws std::runtime_error (with GLFW's reason) when there is no display or no suitable context.
    GlfwWindow(int width, int height, const std::string& title);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool should_close() const;
    void request_close();
    void swap_buffers();
    WindowEvents take_events();
    // Counts every input and window event GLFW has delivered (keys, characters, the mouse, focus, size,
    // exposure), so the viewer can tell a wake-up with something to draw from a timeout.
    std::uint64_t event_count() const { return event_count_; }

  private:
    static void on_scroll(GLFWwindow* window, double dx, double dy);
    static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void on_drop(GLFWwindow* window, int count, const char** paths);
    static void count_event(GLFWwindow* window);
    void note_press();
    static void on_mouse_button(GLFWwindow* window, int button, int action, int mods);

    GLFWwindow* window_ = nullptr;
    WindowEvents events_;
    std::uint64_t event_count_ = 0;
};

}  // namespace rad
