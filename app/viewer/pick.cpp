#include "viewer/pick.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <limits>

namespace rad {

PickRay pick_ray(const glm::mat4& view_projection, const glm::dvec2& ndc) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view_projection));
    const glm::dvec4 near_point = inverse * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 far_point = inverse * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 a = glm::dvec3(near_point) / near_point.w;
    const glm::dvec3 b = glm::dvec3(far_point) / far_point.w;
    return {a, glm::normalize(b - a)};
}

std::optional<std::uint32_t> pick_triangle(std::span<const glm::vec3> positions,
                                           std::span<const std::uint32_t> triangles, const PickRay& ray) {
    std::optional<std::uint32_t> nearest;
    double nearest_t = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const glm::dvec3 a(positions[triangles[t]]);
        const glm::dvec3 b(positions[triangles[t + 1]]);
        const glm::dvec3 c(positions[triangles[t + 2]]);
        const glm::dvec3 ab = b - a, ac = c - a;
        // Möller and Trumbore: the determinant is −d · (ab × ac), positive where the ray meets the front
        // (corners counter-clockwise seen from the ray's origin).
        const glm::dvec3 p = glm::cross(ray.direction, ac);
        const double determinant = glm::dot(ab, p);
        if (!(determinant > 0.0)) continue;
        const glm::dvec3 s = ray.origin - a;
        const double u = glm::dot(s, p) / determinant;
        if (u < 0.0 || u > 1.0) continue;
        const glm::dvec3 q = glm::cross(s, ab);
        const double v = glm::dot(ray.direction, q) / determinant;
        if (v < 0.0 || u + v > 1.0) continue;
        const double distance = glm::dot(ac, q) / determinant;
        if (distance > 0.0 && distance < nearest_t) {
            nearest_t = distance;
            nearest = static_cast<std::uint32_t>(t / 3);
        }
    }
    return nearest;
}

}  // namespace rad
