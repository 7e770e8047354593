#include "viewer/camera_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace rad {

namespace {

int axis(GLFWwindow* window, int positive_key, int negative_key) {
    return (glfwGetKey(window, positive_key) == GLFW_PRESS ? 1 : 0) -
           (glfwGetKey(window, negative_key) == GLFW_PRESS ? 1 : 0);
}

}  // namespace

MoveInput held_move_keys(GLFWwindow* window) {
    MoveInput input;
    input.forward = axis(window, GLFW_KEY_W, GLFW_KEY_S);
    input.right = axis(window, GLFW_KEY_D, GLFW_KEY_A);
    input.up = axis(window, GLFW_KEY_E, GLFW_KEY_Q);
    return input;
}

void CameraInput::update(GLFWwindow* window, FlyCamera& camera, const glm::dvec3& orbit_centre,
                         double seconds, bool keyboard, bool mouse) {
    if (keyboard) camera.move(held_move_keys(window), seconds);

    const bool held = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    double x = 0.0;
    double y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    if (held && dragging_) {
        if (orbit) {
            camera.orbit(orbit_centre, x - last_x_, y - last_y_);
        } else {
            camera.look(x - last_x_, y - last_y_);
        }
    }
    dragging_ = held && (dragging_ || mouse);  // a drag starts only outside the panel
    last_x_ = x;
    last_y_ = y;
}

void CameraInput::release() {
    dragging_ = false;
}

bool CameraInput::moving(GLFWwindow* window) const {
    const MoveInput keys = held_move_keys(window);
    return dragging_ || keys.forward != 0 || keys.right != 0 || keys.up != 0;
}

}  // namespace rad
