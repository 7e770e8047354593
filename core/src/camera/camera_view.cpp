#include "rad/camera/camera_view.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rad {

Camera frame_bounding_box(const BoundingBox& box, double fov_degrees) {
    const glm::dvec3 centre = box.empty() ? glm::dvec3(0.0) : (box.min + box.max) * 0.5;
    const double radius = std::max(0.5 * glm::length(box.extent()), 1e-9);
    const double distance = radius / std::sin(glm::radians(fov_degrees) * 0.5);
    Camera camera;
    camera.target = centre;
    camera.eye = centre + distance * glm::normalize(glm::dvec3(0.35, 0.3, 1.0));
    camera.up = {0.0, 1.0, 0.0};
    camera.fov_degrees = fov_degrees;
    return camera;
}

Camera scene_camera(const Scene& scene) {
    return scene.camera ? *scene.camera : frame_bounding_box(bounding_box(scene));
}

glm::mat4 view_projection(const Camera& camera, double aspect, const BoundingBox& scene_box) {
    const glm::dvec3 centre = scene_box.empty() ? camera.target : (scene_box.min + scene_box.max) * 0.5;
    const double radius = std::max(0.5 * glm::length(scene_box.extent()), 1e-9);
    const double to_centre = glm::length(centre - camera.eye);
    const double far_plane = (to_centre + radius) * 1.01;
    // Close enough for an eye inside the scene, far enough to keep depth precision.
    const double near_plane = std::max(to_centre - radius, far_plane * 1e-4);
    const glm::dmat4 projection =
        glm::perspective(glm::radians(camera.fov_degrees), aspect, near_plane, far_plane);
    const glm::dmat4 view = glm::lookAt(camera.eye, camera.target, camera.up);
    return glm::mat4(projection * view);
}

}  // namespace rad
