#include "scene/convex_split.hpp"

#include <glm/geometric.hpp>

namespace rad {

ConvexSplit split_convex(const std::vector<glm::dvec3>& polygon, const glm::dvec3& normal, double offset,
                         double tolerance) {
    std::vector<double> d(polygon.size());
    bool any_front = false, any_back = false;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        d[k] = glm::dot(normal, polygon[k]) - offset;
        if (d[k] > tolerance) any_front = true;
        if (d[k] < -tolerance) any_back = true;
    }
    ConvexSplit out;
    if (!any_back) {
        out.front = polygon;
        return out;
    }
    if (!any_front) {
        out.back = polygon;
        return out;
    }
    // Sutherland-Hodgman against both half-spaces at once; corners on the plane go to both parts.
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const std::size_t next = (k + 1) % polygon.size();
        const bool on = std::abs(d[k]) <= tolerance;
        if (on || d[k] > 0.0) out.front.push_back(polygon[k]);
        if (on || d[k] < 0.0) out.back.push_back(polygon[k]);
        const bool crosses =
            (d[k] > tolerance && d[next] < -tolerance) || (d[k] < -tolerance && d[next] > tolerance);
        if (crosses) {
            const double t = d[k] / (d[k] - d[next]);
            const glm::dvec3 p = polygon[k] + t * (polygon[next] - polygon[k]);
            out.front.push_back(p);
            out.back.push_back(p);
        }
    }
    return out;
}

}  // namespace rad
