#pragma once

#include <glm/vec3.hpp>

#include "rad/camera/fly_camera.hpp"

struct GLFWwindow;

namespace rad {

// Drives a FlyCamera from the keyboard and mouse, once per frame: W A S D fly, Q and E go down and up, the
// right mouse button held looks around (or, in orbit mode, turns around the scene's centre). Movement uses
// the frame's duration, so it does not depend on the frame rate.
class CameraInput {
  public:
    // keyboard and mouse: false while the panel has them (typing in a text field must not fly the camera).
    void update(GLFWwindow* window, FlyCamera& camera, const glm::dvec3& orbit_centre, double seconds,
                bool keyboard, bool mouse);
    // Forgets the drag in progress, so the view does not jump when focus comes back.
    void release();
    // A move key is held or the view is being dragged: the camera changes every frame, without events.
    bool moving(GLFWwindow* window) const;

    bool orbit = false;

  private:
    bool dragging_ = false;
    double last_x_ = 0.0;
    double last_y_ = 0.0;
};

// The keys held now, as FlyCamera wants them.
MoveInput held_move_keys(GLFWwindow* window);

}  // namespace rad
