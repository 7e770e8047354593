#include "scene/solid_components.hpp"

#include <algorithm>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>
#include <span>
#include <unordered_map>

#include "rad/geometry/polygon.hpp"
#include "scene/soup_corners.hpp"

namespace rad {

namespace {

// One use of an edge by a polygon: the edge's corners (smaller id first) and whether the polygon runs it
// from the smaller to the larger.
struct EdgeUse {
    std::uint64_t key = 0;
    std::uint32_t polygon = 0;
    std::uint32_t corner = 0;  // the edge runs from this corner of the polygon to the next
    std::uint32_t group = 0;
    bool forward = false;
};

std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

std::vector<EdgeUse> edge_uses(const std::vector<std::vector<glm::dvec3>>& polygons,
                               const std::vector<std::uint32_t>& groups) {
    std::unordered_map<glm::dvec3, std::uint32_t, PositionHash> ids;
    const auto id = [&](const glm::dvec3& p) {
        return ids.try_emplace(p, static_cast<std::uint32_t>(ids.size())).first->second;
    };
    std::vector<EdgeUse> uses;
    for (std::uint32_t i = 0; i < polygons.size(); ++i) {
        const auto& points = polygons[i];
        for (std::size_t k = 0; k < points.size(); ++k) {
            const std::uint64_t a = id(points[k]), b = id(points[(k + 1) % points.size()]);
            uses.push_back(
                {std::min(a, b) << 32 | std::max(a, b), i, static_cast<std::uint32_t>(k), groups[i], a < b});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return x.group != y.group ? x.group < y.group : x.key < y.key;
    });
    return uses;
}

// Where more than two faces meet at an edge (two solids sharing an edge, as slabs meeting at a corner), each
// face closes with its neighbour around the edge when the wedge between the two lies behind both: the
// faces are sorted by angle about the edge and each consecutive pair's wedge tested at its bisector. Joins
// the faces so paired; false when some face finds no partner or more than one.
bool pair_around_edge(const std::vector<std::vector<glm::dvec3>>& polygons, std::span<const EdgeUse> uses,
                      std::vector<std::uint32_t>& parent) {
    const auto& p0 = polygons[uses[0].polygon];
    glm::dvec3 a = p0[uses[0].corner], b = p0[(uses[0].corner + 1) % p0.size()];
    if (!uses[0].forward) std::swap(a, b);
    const glm::dvec3 d = glm::normalize(b - a);
    // A frame about the edge from a direction no modeller's edge follows, so that no face lies at ±π.
    glm::dvec3 x = glm::cross(d, glm::dvec3(0.2673, 0.5345, 0.8018));
    if (glm::dot(x, x) < 1e-6) x = glm::cross(d, glm::dvec3(0.8018, -0.2673, 0.5345));
    x = glm::normalize(x);
    const glm::dvec3 y = glm::cross(d, x);
    struct Around {
        double angle, ahead;
        glm::dvec3 normal;
        std::uint32_t polygon;
    };
    std::vector<Around> around;
    for (const EdgeUse& u : uses) {
        const auto& points = polygons[u.polygon];
        glm::dvec3 c(0.0);
        for (const glm::dvec3& p : points) c += p;
        c = c / static_cast<double>(points.size()) - a;
        const glm::dvec3 w = c - glm::dot(c, d) * d;
        const double angle = std::atan2(glm::dot(w, y), glm::dot(w, x));
        const glm::dvec3 n = glm::normalize(newell_normal(points));
        // Along the turn: two faces back to back (solids touching) tie in angle, and the one whose front
        // looks ahead comes first, so that each closes with the neighbour behind it.
        const double ahead = glm::dot(n, -std::sin(angle) * x + std::cos(angle) * y);
        around.push_back({angle, ahead, n, u.polygon});
    }
    std::sort(around.begin(), around.end(), [](const Around& l, const Around& r) {
        return std::abs(l.angle - r.angle) > 1e-9 ? l.angle < r.angle : l.ahead > r.ahead;
    });
    std::vector<int> partners(around.size(), 0);
    for (std::size_t i = 0; i < around.size(); ++i) {
        const std::size_t j = (i + 1) % around.size();
        double span = around[j].angle - around[i].angle;
        if (span <= 0.0) span += 2.0 * std::numbers::pi;
        const double half = around[i].angle + 0.5 * span;
        const glm::dvec3 bisector = std::cos(half) * x + std::sin(half) * y;
        if (glm::dot(around[i].normal, bisector) < 0.0 && glm::dot(around[j].normal, bisector) < 0.0) {
            ++partners[i];
            ++partners[j];
            parent[find(parent, around[i].polygon)] = find(parent, around[j].polygon);
        }
    }
    return std::all_of(partners.begin(), partners.end(), [](int n) { return n == 1; });
}

// Six times the signed volume the polygons enclose (fans from the origin).
double volume6(const std::vector<std::vector<glm::dvec3>>& polygons, const std::vector<std::uint32_t>& set) {
    double sum = 0.0;
    for (std::uint32_t i : set) {
        const auto& p = polygons[i];
        for (std::size_t k = 1; k + 1 < p.size(); ++k) sum += glm::dot(p[0], glm::cross(p[k], p[k + 1]));
    }
    return sum;
}

}  // namespace

Solids find_solids(const std::vector<std::vector<glm::dvec3>>& polygons,
                   const std::vector<std::uint32_t>& groups) {
    const std::vector<EdgeUse> uses = edge_uses(polygons, groups);
    std::vector<std::uint32_t> parent(polygons.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<bool> open(polygons.size(), false);
    for (std::size_t first = 0; first < uses.size();) {
        std::size_t last = first;
        while (last < uses.size() && uses[last].key == uses[first].key &&
               uses[last].group == uses[first].group)
            ++last;
        const std::size_t count = last - first;
        bool closed = false;
        if (count == 2) {
            closed = uses[first].forward != uses[first + 1].forward;
            parent[find(parent, uses[first].polygon)] = find(parent, uses[first + 1].polygon);
        } else if (count > 2 && count % 2 == 0) {
            closed = pair_around_edge(polygons, std::span<const EdgeUse>(uses).subspan(first, count), parent);
        }
        if (!closed)
            for (std::size_t k = first; k < last; ++k) open[uses[k].polygon] = true;
        first = last;
    }
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> components;
    std::unordered_map<std::uint32_t, bool> component_open;
    for (std::uint32_t i = 0; i < polygons.size(); ++i) {
        if (polygons[i].size() < 3) continue;
        const std::uint32_t root = find(parent, i);
        components[root].push_back(i);
        component_open[root] = component_open[root] || open[i];
    }
    Solids solids;
    solids.of_polygon.assign(polygons.size(), kNoSolid);
    std::vector<std::uint32_t> roots;
    for (const auto& [root, set] : components) roots.push_back(root);
    std::sort(roots.begin(), roots.end());  // a stable numbering, whatever the map's order
    for (std::uint32_t root : roots) {
        const std::vector<std::uint32_t>& set = components[root];
        if (component_open[root] || set.size() < 4) continue;
        glm::dvec3 lo = polygons[set[0]][0], hi = lo;
        for (std::uint32_t i : set)
            for (const glm::dvec3& p : polygons[i]) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const double size = glm::length(hi - lo);
        // Faces outwards, and not flat (two faces back to back close with no volume).
        if (!(volume6(polygons, set) > 6e-9 * size * size * size)) continue;
        const auto solid = static_cast<std::uint32_t>(solids.polygons.size());
        for (std::uint32_t i : set) solids.of_polygon[i] = solid;
        solids.polygons.push_back(set);
    }
    return solids;
}

}  // namespace rad
