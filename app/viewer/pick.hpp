#pragma once

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>

namespace rad {

// A ray through a point of the view: `ndc` in [-1, 1]² (x right, y up), through the inverse of the
// projection × view the view was drawn with.
struct PickRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0};  // unit
};
PickRay pick_ray(const glm::mat4& view_projection, const glm::dvec2& ndc);

// The nearest triangle the ray meets from its front (the side drawn; back faces are culled), as an index
// into `triangles` (three vertex indices each); nothing where it meets none. Every triangle is tried: a
// click is rare, and a million triangles take milliseconds.
std::optional<std::uint32_t> pick_triangle(std::span<const glm::vec3> positions,
                                           std::span<const std::uint32_t> triangles, const PickRay& ray);

}  // namespace rad
