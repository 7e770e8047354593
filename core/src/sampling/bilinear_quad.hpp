#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace rad {

// The bilinear map of the unit square onto a quad abcd and its Jacobian |dp/du x dp/dv|: a point drawn
// uniformly in the square and weighted by jacobian / area is area-uniform on any quad, planar or not.
struct BilinearQuad {
    glm::dvec3 a, b, c, d;

    glm::dvec3 point(const glm::dvec2& u) const {
        return (1 - u.x) * (1 - u.y) * a + u.x * (1 - u.y) * b + u.x * u.y * c + (1 - u.x) * u.y * d;
    }
    double jacobian(const glm::dvec2& u) const {
        const glm::dvec3 du = (1 - u.y) * (b - a) + u.y * (c - d);
        const glm::dvec3 dv = (1 - u.x) * (d - a) + u.x * (c - b);
        return glm::length(glm::cross(du, dv));
    }
};

}  // namespace rad
