#include "scene/gltf/gltf_quads.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

namespace rad {

namespace {

using Quad = std::array<std::uint32_t, 4>;

struct Edge {
    std::uint32_t from, to, triangle;
    auto operator<=>(const Edge&) const = default;
};

// Whether the quad's corners lie in one plane and turn the same way at every corner.
bool planar_convex(const Quad& q, const std::vector<glm::dvec3>& p) {
    const glm::dvec3 normal =
        glm::cross(p[q[1]] - p[q[0]], p[q[2]] - p[q[0]]) + glm::cross(p[q[2]] - p[q[0]], p[q[3]] - p[q[0]]);
    const double n = glm::length(normal);
    double size = 0.0;
    for (int k = 0; k < 4; ++k) size = std::max(size, glm::length(p[q[(k + 1) % 4]] - p[q[k]]));
    if (!(n > 0.0) || !(size > 0.0)) return false;
    const glm::dvec3 unit = normal / n;
    for (int k = 0; k < 4; ++k) {
        if (std::abs(glm::dot(p[q[k]] - p[q[0]], unit)) > 1e-7 * size) return false;
        const glm::dvec3 turn =
            glm::cross(p[q[(k + 1) % 4]] - p[q[k]], p[q[(k + 2) % 4]] - p[q[(k + 1) % 4]]);
        if (!(glm::dot(turn, unit) > 1e-12 * size * size)) return false;
    }
    return true;
}

}  // namespace

std::vector<std::vector<std::uint32_t>> merge_triangle_pairs(const std::vector<std::uint32_t>& corners,
                                                             const std::vector<glm::dvec3>& positions) {
    const std::size_t count = corners.size() / 3;
    // Directed edges a -> b with the triangle that runs along each, sorted for lookup (12 bytes an edge,
    // where a map would take several times that on a large mesh).
    std::vector<Edge> edges;
    edges.reserve(3 * count);
    for (std::size_t t = 0; t < count; ++t)
        for (int k = 0; k < 3; ++k)
            edges.push_back(
                {corners[3 * t + k], corners[3 * t + (k + 1) % 3], static_cast<std::uint32_t>(t)});
    std::sort(edges.begin(), edges.end());
    std::vector<bool> used(count, false);
    std::vector<std::vector<std::uint32_t>> polygons;
    for (std::size_t t = 0; t < count; ++t) {
        if (used[t]) continue;
        used[t] = true;
        std::vector<std::uint32_t> polygon(corners.begin() + static_cast<std::ptrdiff_t>(3 * t),
                                           corners.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
        for (int k = 0; k < 3; ++k) {
            // Triangle t is (a, b, c) from corner k; its neighbour across a -> b runs b -> a -> d.
            const std::uint32_t a = polygon[k], b = polygon[(k + 1) % 3], c = polygon[(k + 2) % 3];
            const auto other = std::lower_bound(edges.begin(), edges.end(), Edge{b, a, 0});
            if (other == edges.end() || other->from != b || other->to != a || used[other->triangle]) continue;
            const std::size_t u = other->triangle;
            std::uint32_t d = 0;
            for (int j = 0; j < 3; ++j)
                if (corners[3 * u + j] != a && corners[3 * u + j] != b) d = corners[3 * u + j];
            // b, c, a, d: the fan (v1 v2 v3), (v1 v3 v4) of the quad v1..v4 gives back v1..v4.
            const Quad quad{b, c, a, d};
            if (!planar_convex(quad, positions)) continue;
            used[u] = true;
            polygon.assign(quad.begin(), quad.end());
            break;
        }
        polygons.push_back(std::move(polygon));
    }
    return polygons;
}

}  // namespace rad
