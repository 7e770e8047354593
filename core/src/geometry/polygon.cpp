#include "rad/geometry/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <numeric>

namespace rad {

glm::dvec3 newell_normal(std::span<const glm::dvec3> polygon) {
    glm::dvec3 n(0.0);
    const std::size_t count = polygon.size();
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % count];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

double polygon_area(std::span<const glm::dvec3> polygon) {
    return 0.5 * glm::length(newell_normal(polygon));
}

namespace {

double diameter(std::span<const glm::dvec3> polygon) {
    double d = 0.0;
    for (const auto& a : polygon)
        for (const auto& b : polygon) d = std::max(d, glm::length(a - b));
    return d;
}

glm::dvec3 mean_point(std::span<const glm::dvec3> polygon) {
    glm::dvec3 c(0.0);
    for (const auto& p : polygon) c += p;
    return c / static_cast<double>(polygon.size());
}

}  // namespace

bool is_planar_convex(std::span<const glm::dvec3> polygon, double relative_tolerance) {
    const std::size_t count = polygon.size();
    if (count < 3) return false;
    const glm::dvec3 n = newell_normal(polygon);
    const double twice_area = glm::length(n);
    const double size = diameter(polygon);
    if (!(twice_area > 0.0) || !(size > 0.0)) return false;
    const glm::dvec3 unit = n / twice_area;
    const glm::dvec3 centre = mean_point(polygon);
    for (const auto& p : polygon) {
        if (std::abs(glm::dot(p - centre, unit)) > relative_tolerance * size) return false;
    }
    // Every corner turns the same way as the normal, by more than round-off, and all corners together turn
    // once around: a polygon that winds twice (a pentagram, or a triangle traced twice) turns the same way
    // at every corner too, and repeats or crosses itself.
    double turning = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 e0 = polygon[(i + 1) % count] - polygon[i];
        const glm::dvec3 e1 = polygon[(i + 2) % count] - polygon[(i + 1) % count];
        const double across = glm::dot(glm::cross(e0, e1), unit);  // |e0| |e1| sin(turn)
        if (across <= 1e-12 * size * size) return false;
        turning += std::atan2(across, glm::dot(e0, e1));
    }
    return turning < 3.0 * std::numbers::pi;  // 2π for a convex polygon, 2πk for one that winds k times
}

namespace {

// Project onto the plane most aligned with the normal, keeping the winding counter-clockwise.
std::vector<glm::dvec2> project_to_plane(std::span<const glm::dvec3> polygon, const glm::dvec3& n) {
    const glm::dvec3 a = glm::abs(n);
    const int drop = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    const int u = (drop + 1) % 3;
    const int v = (drop + 2) % 3;
    const double sign = n[drop] >= 0.0 ? 1.0 : -1.0;
    std::vector<glm::dvec2> out;
    out.reserve(polygon.size());
    for (const auto& p : polygon) out.emplace_back(p[u], sign * p[v]);
    return out;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) {
    return a.x * b.y - a.y * b.x;
}

bool point_in_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return cross2(b - a, p - a) >= 0.0 && cross2(c - b, p - b) >= 0.0 && cross2(a - c, p - c) >= 0.0;
}

bool is_ear(const std::vector<glm::dvec2>& pts, const std::vector<std::size_t>& ring, std::size_t k) {
    const std::size_t m = ring.size();
    const glm::dvec2& a = pts[ring[(k + m - 1) % m]];
    const glm::dvec2& b = pts[ring[k]];
    const glm::dvec2& c = pts[ring[(k + 1) % m]];
    if (cross2(b - a, c - b) <= 0.0) return false;  // reflex or degenerate corner
    for (std::size_t j = 0; j < m; ++j) {
        if (j == k || j == (k + 1) % m || j == (k + m - 1) % m) continue;
        const glm::dvec2& p = pts[ring[j]];
        if (p == a || p == b || p == c) continue;
        if (point_in_triangle(p, a, b, c)) return false;
    }
    return true;
}

std::vector<std::array<std::size_t, 3>> split_quad(std::span<const glm::dvec3> q,
                                                   const std::vector<glm::dvec2>& pts) {
    // Prefer the shorter diagonal, provided it lies inside the quad (both of its corners are convex).
    const bool diag02_ok =
        cross2(pts[1] - pts[0], pts[2] - pts[1]) > 0.0 && cross2(pts[3] - pts[2], pts[0] - pts[3]) > 0.0;
    const bool diag13_ok =
        cross2(pts[2] - pts[1], pts[3] - pts[2]) > 0.0 && cross2(pts[0] - pts[3], pts[1] - pts[0]) > 0.0;
    const bool shorter02 = glm::length(q[2] - q[0]) <= glm::length(q[3] - q[1]);
    if (diag02_ok && (shorter02 || !diag13_ok)) return {{0, 1, 2}, {0, 2, 3}};
    return {{1, 2, 3}, {1, 3, 0}};
}

}  // namespace

std::vector<std::array<std::size_t, 3>> triangulate_polygon(std::span<const glm::dvec3> polygon) {
    const std::size_t count = polygon.size();
    if (count < 3) return {};
    if (count == 3) return {{0, 1, 2}};
    const std::vector<glm::dvec2> pts = project_to_plane(polygon, newell_normal(polygon));
    if (count == 4) return split_quad(polygon, pts);

    std::vector<std::size_t> ring(count);
    std::iota(ring.begin(), ring.end(), 0);
    std::vector<std::array<std::size_t, 3>> triangles;
    while (ring.size() > 3) {
        const std::size_t m = ring.size();
        std::size_t k = 0;
        while (k < m && !is_ear(pts, ring, k)) ++k;
        if (k == m) k = 0;  // self-intersecting input: clip anyway so we always terminate
        triangles.push_back({ring[(k + m - 1) % m], ring[k], ring[(k + 1) % m]});
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
    }
    triangles.push_back({ring[0], ring[1], ring[2]});
    return triangles;
}

}  // namespace rad
