#pragma once

#include <glm/vec3.hpp>

#include "rad/scene/scene.hpp"

namespace rad {

// What the keys held during a frame ask for: each axis in {-1, 0, 1} (W/S forward, D/A right, E/Q up).
struct MoveInput {
    int forward = 0;
    int right = 0;
    int up = 0;
};

// A first-person camera: moves at `speed` scene units per second whatever the frame rate, looks around by
// yaw and pitch (pitch kept short of straight up or down so "up" stays defined), and can orbit a centre.
class FlyCamera {
  public:
    // speed: scene units per second; a tenth of the scene's size per second is a comfortable start.
    FlyCamera(const Camera& start, double speed);

    // Moves by speed × seconds along the camera's forward and right directions and the world's up.
    void move(const MoveInput& input, double seconds);
    // Turns by the mouse's travel in pixels (right and down positive).
    void look(double dx_pixels, double dy_pixels);
    // Each scroll step makes the speed 25 % faster (positive) or slower (negative).
    void scroll_speed(double steps);
    // Turns around `centre` by the mouse's travel, keeping the distance, and looks at it.
    void orbit(const glm::dvec3& centre, double dx_pixels, double dy_pixels);
    void reset();
    // Stands at a view's eye, looking at its target (a view camera() gave: the same up, speed and field of
    // view).
    void go_to(const Camera& view);

    Camera camera() const;
    double speed() const { return speed_; }
    glm::dvec3 forward() const;
    glm::dvec3 right() const;

    static constexpr double kRadiansPerPixel = 0.004;

  private:
    void set_direction(const glm::dvec3& forward);

    Camera start_;
    double start_speed_;
    glm::dvec3 eye_;
    glm::dvec3 world_up_;
    double yaw_ = 0.0;    // about world up, radians
    double pitch_ = 0.0;  // above the horizontal, radians
    double speed_;
    double fov_degrees_;
};

}  // namespace rad
