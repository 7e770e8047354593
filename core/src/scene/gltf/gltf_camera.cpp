#include "scene/gltf/gltf_camera.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "rad/util/error.hpp"

namespace rad {

namespace {

[[noreturn]] void refuse(const GltfFile& file, const std::string& what) {
    throw InputError(gltf_message(file, what));
}

std::optional<Camera> camera_at(const GltfFile& file, const PlacedNode& placed,
                                const tinygltf::Camera& camera, const std::string& where) {
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0.0 && yfov < std::numbers::pi)) refuse(file, where + ": yfov must lie in (0, π)");
    const glm::dmat4& m = placed.world;
    const glm::dvec3 forward(-m[2]);
    const glm::dvec3 up(m[1]);
    // A transform that squashes the camera's frame flat leaves no direction to look in.
    if (!(glm::length(forward) > 0.0) || !(glm::length(glm::cross(forward, up)) > 0.0))
        refuse(file,
               "nodes[" + std::to_string(placed.node) + "]: its transform leaves the camera no direction");
    Camera out;
    out.eye = glm::dvec3(m[3]) / m[3][3];
    out.target = out.eye + glm::normalize(forward);
    out.up = glm::normalize(up);
    out.fov_degrees = yfov * 180.0 / std::numbers::pi;
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(out.eye[c]) || !std::isfinite(out.target[c]) || !std::isfinite(out.up[c]))
            refuse(file, "nodes[" + std::to_string(placed.node) + "]: its camera is not at a finite place");
    return out;
}

}  // namespace

std::optional<Camera> first_camera(GltfFile& file, const std::vector<PlacedNode>& nodes) {
    std::size_t orthographic = 0;
    std::optional<Camera> found;
    const auto& cameras = file.model.cameras;
    for (const PlacedNode& placed : nodes) {
        const int index = file.model.nodes[static_cast<std::size_t>(placed.node)].camera;
        if (index < 0) continue;
        if (static_cast<std::size_t>(index) >= cameras.size())
            refuse(file, "nodes[" + std::to_string(placed.node) + "]: camera " + std::to_string(index) +
                             " does not exist (" + std::to_string(cameras.size()) + " in the file)");
        const tinygltf::Camera& camera = cameras[static_cast<std::size_t>(index)];
        if (camera.type != "perspective") {
            ++orthographic;
            continue;
        }
        if (!found) found = camera_at(file, placed, camera, "cameras[" + std::to_string(index) + "]");
    }
    if (orthographic > 0)
        file.warnings.push_back(gltf_message(file, std::to_string(orthographic) +
                                                       " orthographic camera(s) ignored: only perspective "
                                                       "cameras are read"));
    return found;
}

}  // namespace rad
