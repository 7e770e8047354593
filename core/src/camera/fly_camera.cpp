#include "rad/camera/fly_camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace rad {

namespace {

constexpr double kMaxPitch = 89.0 * std::numbers::pi / 180.0;

// An orthonormal frame around the world's up: `ahead` is where yaw 0 looks.
struct Frame {
    glm::dvec3 up, ahead, side;
};

Frame frame_for(const glm::dvec3& up) {
    const glm::dvec3 u = glm::normalize(up);
    // Any direction not parallel to up serves as yaw 0; prefer -z, the usual "into the screen".
    glm::dvec3 ahead = glm::dvec3(0, 0, -1) - u * glm::dot(glm::dvec3(0, 0, -1), u);
    if (glm::length(ahead) < 1e-6) ahead = glm::dvec3(1, 0, 0) - u * glm::dot(glm::dvec3(1, 0, 0), u);
    ahead = glm::normalize(ahead);
    return {u, ahead, glm::cross(ahead, u)};
}

}  // namespace

FlyCamera::FlyCamera(const Camera& start, double speed)
    : start_(start),
      start_speed_(speed),
      eye_(start.eye),
      world_up_(glm::normalize(start.up)),
      speed_(speed),
      fov_degrees_(start.fov_degrees) {
    set_direction(start.target - start.eye);
}

void FlyCamera::set_direction(const glm::dvec3& direction) {
    const Frame f = frame_for(world_up_);
    const glm::dvec3 d = glm::normalize(direction);
    pitch_ = std::clamp(std::asin(std::clamp(glm::dot(d, f.up), -1.0, 1.0)), -kMaxPitch, kMaxPitch);
    yaw_ = std::atan2(glm::dot(d, f.side), glm::dot(d, f.ahead));
}

glm::dvec3 FlyCamera::forward() const {
    const Frame f = frame_for(world_up_);
    return std::cos(pitch_) * (std::cos(yaw_) * f.ahead + std::sin(yaw_) * f.side) + std::sin(pitch_) * f.up;
}

glm::dvec3 FlyCamera::right() const {
    return glm::normalize(glm::cross(forward(), world_up_));
}

void FlyCamera::move(const MoveInput& input, double seconds) {
    const double step = speed_ * seconds;
    eye_ += step * (double(input.forward) * forward() + double(input.right) * right() +
                    double(input.up) * world_up_);
}

void FlyCamera::look(double dx_pixels, double dy_pixels) {
    yaw_ += dx_pixels * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - dy_pixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void FlyCamera::scroll_speed(double steps) {
    speed_ *= std::pow(1.25, steps);
}

void FlyCamera::orbit(const glm::dvec3& centre, double dx_pixels, double dy_pixels) {
    const double distance = glm::length(eye_ - centre);
    set_direction(centre - eye_);
    look(-dx_pixels, -dy_pixels);  // dragging right swings the eye right, so the view turns left
    eye_ = centre - distance * forward();
}

void FlyCamera::reset() {
    eye_ = start_.eye;
    speed_ = start_speed_;
    set_direction(start_.target - start_.eye);
}

void FlyCamera::go_to(const Camera& view) {
    eye_ = view.eye;
    set_direction(view.target - view.eye);
}

Camera FlyCamera::camera() const {
    Camera c;
    c.eye = eye_;
    c.target = eye_ + forward();
    c.up = world_up_;
    c.fov_degrees = fov_degrees_;
    return c;
}

}  // namespace rad
