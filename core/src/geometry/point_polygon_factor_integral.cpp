#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>

#include "rad/geometry/point_polygon_factor.hpp"

namespace rad {

namespace {

// Corners closer to the clipping plane than this share of the polygon's distance from the plane's point count
// as on the plane, so rounding never cuts slivers off a patch that only touches the plane along an edge.
constexpr double kOnPlaneFraction = 1e-10;

}  // namespace

ConvexPolygon make_convex_polygon(std::span<const glm::dvec3> corners) {
    if (corners.size() > kMaxPolygonCorners)
        throw std::invalid_argument("make_convex_polygon: too many corners");
    ConvexPolygon polygon;
    std::copy(corners.begin(), corners.end(), polygon.corners.begin());
    polygon.count = corners.size();
    return polygon;
}

ConvexPolygon clip_to_front(const ConvexPolygon& polygon, const glm::dvec3& point, const glm::dvec3& normal) {
    std::array<double, kMaxPolygonCorners> side{};
    double scale = 0.0;
    double farthest = 0.0;
    for (std::size_t k = 0; k < polygon.count; ++k) {
        side[k] = glm::dot(normal, polygon.corners[k] - point);
        scale = std::max(scale, glm::length(polygon.corners[k] - point));
    }
    for (std::size_t k = 0; k < polygon.count; ++k) {
        if (std::abs(side[k]) <= kOnPlaneFraction * scale) side[k] = 0.0;
        farthest = std::max(farthest, side[k]);
    }
    ConvexPolygon out;
    if (!(farthest > 0.0)) return out;  // wholly behind the plane or in it
    for (std::size_t k = 0; k < polygon.count && out.count < kMaxPolygonCorners; ++k) {
        const std::size_t next = (k + 1) % polygon.count;
        const glm::dvec3& a = polygon.corners[k];
        const glm::dvec3& b = polygon.corners[next];
        if (side[k] >= 0.0) out.corners[out.count++] = a;
        const bool crosses = (side[k] > 0.0 && side[next] < 0.0) || (side[k] < 0.0 && side[next] > 0.0);
        if (crosses && out.count < kMaxPolygonCorners) {
            out.corners[out.count++] = a + (b - a) * (side[k] / (side[k] - side[next]));
        }
    }
    return out;
}

double point_polygon_factor(const glm::dvec3& x, const glm::dvec3& n, std::span<const glm::dvec3> polygon) {
    double sum = 0.0;
    const std::size_t count = polygon.size();
    for (std::size_t k = 0; k < count; ++k) {
        const glm::dvec3 r0 = polygon[k] - x;
        const glm::dvec3 r1 = polygon[(k + 1) % count] - x;
        const glm::dvec3 c = glm::cross(r0, r1);
        const double length = glm::length(c);
        // An edge through x (or of zero length) subtends no solid angle that n could weigh.
        if (!(length > 0.0)) continue;
        // atan2 of |r0 x r1| and r0 . r1 is the angle between r0 and r1, accurate where acos is not.
        sum += std::atan2(length, glm::dot(r0, r1)) * glm::dot(n, c) / length;
    }
    // Counter-clockwise from the front, seen from a point in front, the edge normals point away from n.
    return -sum / (2.0 * std::numbers::pi);
}

}  // namespace rad
