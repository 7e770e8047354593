#include "rad/camera/camera_view.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <vector>

#include "rad/geometry/polygon.hpp"

namespace rad {

namespace {

// From the centre towards the eye: in front (+z), a little from above and the right.
const glm::dvec3 kFrontView = glm::normalize(glm::dvec3(0.35, 0.3, 1.0));

// Twice the area of a face along its front normal, and its centroid.
struct FaceArea {
    glm::dvec3 vector{0.0};
    glm::dvec3 centre{0.0};
};

FaceArea face_area_vector(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face) {
    std::vector<glm::dvec3> corners;
    for (auto v : mesh.fv_range(face)) corners.push_back(to_glm(mesh.point(v)));
    FaceArea area;
    if (corners.empty()) return area;
    area.vector = newell_normal(corners);
    for (const glm::dvec3& c : corners) area.centre += c;
    area.centre /= double(corners.size());
    return area;
}

// The views tried, the usual one first: from the front, the right, behind and the left (turned about +y),
// each from a little to the right, to the left, and straight on (a room's side walls both face an eye
// straight in front of its opening; one offset to a side would stand beyond that side's wall).
std::vector<glm::dvec3> candidate_views() {
    std::vector<glm::dvec3> views;
    for (const double side : {0.35, -0.35, 0.0}) {
        glm::dvec3 v = glm::normalize(glm::dvec3(side, 0.3, 1.0));
        for (int turns = 0; turns < 4; ++turns) {
            views.push_back(v);
            v = glm::dvec3(v.z, v.y, -v.x);
        }
    }
    return views;
}

}  // namespace

Camera frame_bounding_box(const BoundingBox& box, double fov_degrees, const glm::dvec3& towards_eye) {
    const glm::dvec3 centre = box.empty() ? glm::dvec3(0.0) : (box.min + box.max) * 0.5;
    const double radius = std::max(0.5 * glm::length(box.extent()), 1e-9);
    const double distance = radius / std::sin(glm::radians(fov_degrees) * 0.5);
    Camera camera;
    camera.target = centre;
    camera.eye = centre + distance * glm::normalize(towards_eye);
    camera.up = {0.0, 1.0, 0.0};
    camera.fov_degrees = fov_degrees;
    return camera;
}

Camera frame_bounding_box(const BoundingBox& box, double fov_degrees) {
    return frame_bounding_box(box, fov_degrees, kFrontView);
}

glm::dvec3 front_side(const Scene& scene, double fov_degrees) {
    std::vector<FaceArea> faces;
    double total = 0.0;
    for (const Surface& surface : scene.surfaces) {
        for (auto face : surface.mesh.faces()) {
            faces.push_back(face_area_vector(surface.mesh, face));
            total += glm::length(faces.back().vector);
        }
    }
    // Each face counts its area as the eye sees it: positive from its front, negative from behind (culled,
    // so the eye looks through it). A closed room shows as much of one as of the other from every side.
    const BoundingBox box = bounding_box(scene);
    const std::vector<glm::dvec3> views = candidate_views();
    std::size_t best = 0;
    double best_seen = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < views.size(); ++i) {
        const glm::dvec3 eye = frame_bounding_box(box, fov_degrees, views[i]).eye;
        double seen = 0.0;
        for (const FaceArea& face : faces) {
            const glm::dvec3 to_eye = eye - face.centre;
            const double distance = glm::length(to_eye);
            if (distance > 0.0) seen += glm::dot(face.vector, to_eye) / distance;
        }
        // Another view only when it clearly shows more: symmetric and closed scenes keep the usual one.
        if (i == 0 || seen > best_seen + 0.01 * total) {
            best = i;
            best_seen = seen;
        }
    }
    return views[best];
}

Camera scene_camera(const Scene& scene) {
    return scene.camera ? *scene.camera
                        : frame_bounding_box(bounding_box(scene), 45.0, front_side(scene, 45.0));
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
