#include "viewer/glfw_window.hpp"

#include <glad/gl.h>

// glad declares the GL functions; GLFW must not include its own GL header.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <utility>

namespace rad {

namespace {

std::string last_glfw_error() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown reason";
}

GlfwWindow& owner(GLFWwindow* window) {
    return *static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window));
}

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) {
    if (!glfwInit()) throw std::runtime_error("cannot open a window: " + last_glfw_error());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    // No multisampling: with a software rasterizer (llvmpipe, Xvfb) 4 samples made frames 4 times slower,
    // over 100 ms while form factors ran. Screenshots differ from `render`'s 4-sample PNGs at edges only.
    glfwWindowHint(GLFW_SAMPLES, 0);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string reason = last_glfw_error();
        glfwTerminate();
        throw std::runtime_error("cannot open an OpenGL 3.3 window: " + reason);
    }
    glfwMakeContextCurrent(window_);
    if (gladLoadGL(glfwGetProcAddress) < GLAD_MAKE_VERSION(3, 3)) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw std::runtime_error("cannot load the OpenGL 3.3 functions of the window's context");
    }
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetScrollCallback(window_, on_scroll);
    glfwSetKeyCallback(window_, on_key);
    glfwSetDropCallback(window_, on_drop);
    // Dear ImGui's backend, installed after these, calls them from its own callbacks.
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) { count_event(w); });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { count_event(w); });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { count_event(w); });
    glfwSetMouseButtonCallback(window_, on_mouse_button);
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { count_event(w); });
    glfwSetWindowSizeCallback(window_, [](GLFWwindow* w, int, int) { count_event(w); });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { count_event(w); });
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { count_event(w); });
    glfwSetWindowIconifyCallback(window_, [](GLFWwindow* w, int) { count_event(w); });
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlfwWindow::should_close() const {
    return glfwWindowShouldClose(window_);
}

void GlfwWindow::request_close() {
    glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GlfwWindow::swap_buffers() {
    glfwSwapBuffers(window_);
}

WindowEvents GlfwWindow::take_events() {
    return std::exchange(events_, WindowEvents{});
}

void GlfwWindow::note_press() {
    if (!events_.first_press) events_.first_press = glfwGetTime();
}

void GlfwWindow::count_event(GLFWwindow* window) {
    ++owner(window).event_count_;
}

void GlfwWindow::on_mouse_button(GLFWwindow* window, int button, int action, int) {
    count_event(window);
    if (action == GLFW_PRESS) owner(window).note_press();
    if (button != GLFW_MOUSE_BUTTON_LEFT || action != GLFW_PRESS) return;
    glm::dvec2 at(0.0);
    glfwGetCursorPos(window, &at.x, &at.y);
    owner(window).events_.clicks.push_back(at);
}

void GlfwWindow::on_scroll(GLFWwindow* window, double, double dy) {
    count_event(window);
    owner(window).events_.scroll += dy;
}

void GlfwWindow::on_key(GLFWwindow* window, int key, int, int action, int) {
    count_event(window);
    if (action != GLFW_PRESS) return;
    owner(window).note_press();
    owner(window).events_.pressed_keys.push_back(key);
}

void GlfwWindow::on_drop(GLFWwindow* window, int count, const char** paths) {
    count_event(window);
    for (int i = 0; i < count; ++i) owner(window).events_.dropped.emplace_back(paths[i]);
}

}  // namespace rad
