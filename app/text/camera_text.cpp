#include "text/camera_text.hpp"

#include <cstdio>
#include <glm/geometric.hpp>
#include <vector>

#include "rad/util/error.hpp"
#include "text/comma_numbers.hpp"

namespace rad {

namespace {

glm::dvec3 vec(const std::vector<double>& v, std::size_t at) {
    return {v[at], v[at + 1], v[at + 2]};
}

std::string numbers(const glm::dvec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "%.7g,%.7g,%.7g", v.x, v.y, v.z);
    return text;
}

std::string camera_numbers(const Camera& camera) {
    return numbers(camera.eye) + "," + numbers(camera.target) + "," + numbers(camera.up);
}

std::string fov_text(double fov_degrees) {
    char fov[32];
    std::snprintf(fov, sizeof fov, "%.6g", fov_degrees);
    return fov;
}

}  // namespace

Camera parse_camera(const std::string& text, const Camera& fallback, const std::string& where) {
    const std::vector<double> values = comma_numbers(text, where, "ex,ey,ez,tx,ty,tz[,ux,uy,uz]");
    if (values.size() != 6 && values.size() != 9) {
        throw InputError(where + ": " + std::to_string(values.size()) +
                         " numbers; want 6 (eye, target) or 9 (eye, target, up)");
    }
    Camera camera = fallback;
    camera.eye = vec(values, 0);
    camera.target = vec(values, 3);
    if (values.size() == 9) camera.up = vec(values, 6);
    if (glm::length(camera.target - camera.eye) == 0.0) throw InputError(where + ": eye and target coincide");
    if (glm::length(glm::cross(camera.target - camera.eye, camera.up)) == 0.0) {
        throw InputError(where + ": the up vector is zero or points along the view direction");
    }
    return camera;
}

std::string camera_option_text(const Camera& camera) {
    return "--camera " + camera_numbers(camera) + " --fov " + fov_text(camera.fov_degrees);
}

std::string cameras_file_text(const std::vector<Camera>& cameras) {
    std::string text;
    if (!cameras.empty()) {
        text = "# views kept in the viewer; field of view " + fov_text(cameras.front().fov_degrees) +
               " (--fov)\n";
    }
    for (const Camera& camera : cameras) text += camera_numbers(camera) + "\n";
    return text;
}

}  // namespace rad
