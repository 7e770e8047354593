#pragma once

struct GLFWwindow;

namespace rad {

// Dear ImGui's context and its GLFW and OpenGL 3 backends for one window, for as long as this lives. Create
// it after the window's own callbacks are set: the GLFW backend chains them after its own.
class ImGuiLayer {
  public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void begin_frame();
    // Draws the panel into the bound framebuffer, without the sRGB curve (ImGui's colours are already sRGB).
    void end_frame();
    bool wants_keyboard() const;
    bool wants_mouse() const;
};

}  // namespace rad
