#include "display/seam_vertices.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rad {

namespace {

// A point quantized to the matching tolerance, as a hash key.
struct PointKey {
    std::int64_t x, y, z;
    bool operator==(const PointKey&) const = default;
    bool operator<(const PointKey& o) const { return std::tie(x, y, z) < std::tie(o.x, o.y, o.z); }
};

struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const {
        return static_cast<std::size_t>(k.x * 73856093 ^ k.y * 19349663 ^ k.z * 83492791);
    }
};

struct EdgeKey {
    PointKey a, b;
    bool operator==(const EdgeKey&) const = default;
    bool operator<(const EdgeKey& o) const { return a < o.a || (a == o.a && b < o.b); }
};

struct EdgeKeyHash {
    std::size_t operator()(const EdgeKey& k) const {
        return PointKeyHash{}(k.a) * 31 ^ PointKeyHash {}(k.b);
    }
};

class Quantizer {
  public:
    explicit Quantizer(double step) : step_(step) {}
    PointKey key(const glm::vec3& p) const {
        return {std::llround(p.x / step_), std::llround(p.y / step_), std::llround(p.z / step_)};
    }
    EdgeKey edge(const glm::vec3& p, const glm::vec3& q) const {
        PointKey a = key(p), b = key(q);
        if (b < a) std::swap(a, b);
        return {a, b};
    }

  private:
    double step_;
};

// The end points of edges that no other triangle has (by position), in a grid of cells for lookup.
class BoundaryPoints {
  public:
    BoundaryPoints(double cell) : cell_(cell) {}
    void add(std::uint32_t vertex, const glm::vec3& p) { cells_[cell_of(p)].push_back(vertex); }
    // Calls visit(vertex) for the points in the cells the box [low, high] touches.
    template <typename Visit>
    void near(const glm::vec3& low, const glm::vec3& high, Visit visit) const {
        const PointKey a = cell_of(low), b = cell_of(high);
        for (std::int64_t x = a.x; x <= b.x; ++x)
            for (std::int64_t y = a.y; y <= b.y; ++y)
                for (std::int64_t z = a.z; z <= b.z; ++z) {
                    const auto it = cells_.find({x, y, z});
                    if (it == cells_.end()) continue;
                    for (std::uint32_t v : it->second) visit(v);
                }
    }

  private:
    PointKey cell_of(const glm::vec3& p) const {
        return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
                static_cast<std::int64_t>(std::floor(p.y / cell_)),
                static_cast<std::int64_t>(std::floor(p.z / cell_))};
    }
    double cell_;
    std::unordered_map<PointKey, std::vector<std::uint32_t>, PointKeyHash> cells_;
};

struct EdgePoint {
    double t;  // along the edge, in (0, 1)
    std::uint32_t vertex;
};

// A vertex made between vertices a and b (share t of the way), or at the mean of three.
std::uint32_t add_blended_vertex(DisplayMesh& d, std::span<const std::pair<std::uint32_t, double>> parts) {
    const auto vertex = static_cast<std::uint32_t>(d.positions.size());
    glm::dvec3 position(0.0), normal(0.0);
    glm::dvec2 texcoord(0.0);
    std::vector<std::pair<std::uint32_t, double>> weights;
    for (const auto& [v, share] : parts) {
        position += share * glm::dvec3(d.positions[v]);
        normal += share * glm::dvec3(d.normals[v]);
        if (!d.texcoords.empty()) texcoord += share * glm::dvec2(d.texcoords[v]);
        for (std::uint32_t k = d.weight_begin[v]; k < d.weight_begin[v + 1]; ++k)
            weights.emplace_back(d.weight_patch[k], share * d.weight[k]);
    }
    std::sort(weights.begin(), weights.end());
    for (std::size_t k = 0; k < weights.size(); ++k) {
        double sum = weights[k].second;
        while (k + 1 < weights.size() && weights[k + 1].first == weights[k].first) sum += weights[++k].second;
        d.weight_patch.push_back(weights[k].first);
        d.weight.push_back(static_cast<float>(sum));
    }
    d.weight_begin.push_back(static_cast<std::uint32_t>(d.weight.size()));
    d.positions.emplace_back(position);
    d.normals.emplace_back(glm::length(normal) > 0.0 ? glm::normalize(normal)
                                                     : glm::dvec3(d.normals[parts[0].first]));
    if (!d.texcoords.empty()) d.texcoords.emplace_back(texcoord);
    return vertex;
}

double mesh_size(const DisplayMesh& d) {
    glm::vec3 low(INFINITY), high(-INFINITY);
    for (const glm::vec3& p : d.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    return d.positions.empty() ? 0.0 : static_cast<double>(glm::length(high - low));
}

// Per triangle edge (3 t + k, from corner k), 1 where no other triangle has an edge between the same two
// points: a surface's border, or a seam.
std::vector<std::uint8_t> boundary_edges(const DisplayMesh& display, const Quantizer& quantize) {
    std::vector<std::pair<EdgeKey, std::uint32_t>> edges;
    edges.reserve(3 * display.triangles.size());
    for (std::size_t t = 0; t < display.triangles.size(); ++t) {
        const glm::uvec3& c = display.triangles[t];
        for (int k = 0; k < 3; ++k) {
            edges.emplace_back(quantize.edge(display.positions[c[k]], display.positions[c[(k + 1) % 3]]),
                               static_cast<std::uint32_t>(3 * t + k));
        }
    }
    std::sort(edges.begin(), edges.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::uint8_t> open(edges.size(), 0);
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].first == edges[i].first) ++j;
        if (j - i == 1) open[edges[i].second] = 1;
        i = j;
    }
    return open;
}

}  // namespace

void close_seams(DisplayMesh& display) {
    const double size = mesh_size(display);
    if (!(size > 0.0)) return;
    const double tolerance = 1e-6 * size;
    const Quantizer quantize(4.0 * tolerance);
    const std::vector<std::uint8_t> open = boundary_edges(display, quantize);
    // The boundary edges' end points, in cells about an edge long.
    double length = 0.0;
    std::size_t boundary = 0;
    for (std::size_t e = 0; e < open.size(); ++e) {
        if (!open[e]) continue;
        const glm::uvec3& t = display.triangles[e / 3];
        length += glm::length(glm::dvec3(display.positions[t[(e + 1) % 3]] - display.positions[t[e % 3]]));
        ++boundary;
    }
    if (boundary == 0) return;
    BoundaryPoints points(std::max(length / static_cast<double>(boundary), 16.0 * tolerance));
    for (std::size_t e = 0; e < open.size(); ++e) {
        if (!open[e]) continue;
        const glm::uvec3& t = display.triangles[e / 3];
        points.add(t[e % 3], display.positions[t[e % 3]]);
        points.add(t[(e + 1) % 3], display.positions[t[(e + 1) % 3]]);
    }
    // The points strictly inside each boundary edge, along it.
    const auto inside = [&](std::uint32_t from, std::uint32_t to, std::vector<EdgePoint>& out) {
        out.clear();
        const glm::dvec3 a(display.positions[from]), b(display.positions[to]);
        const glm::dvec3 ab = b - a;
        const double l2 = glm::dot(ab, ab);
        if (!(l2 > 0.0)) return;
        const double margin = tolerance / std::sqrt(l2);
        const glm::vec3 pad(static_cast<float>(tolerance));
        points.near(glm::min(display.positions[from], display.positions[to]) - pad,
                    glm::max(display.positions[from], display.positions[to]) + pad, [&](std::uint32_t v) {
                        const glm::dvec3 p(display.positions[v]);
                        const double t = glm::dot(p - a, ab) / l2;
                        if (t <= margin || t >= 1.0 - margin) return;
                        if (glm::length(p - (a + t * ab)) > tolerance) return;
                        out.push_back({t, v});
                    });
        std::sort(out.begin(), out.end(), [](const EdgePoint& x, const EdgePoint& y) { return x.t < y.t; });
        // The same point from several surfaces' edges once.
        out.erase(std::unique(out.begin(), out.end(),
                              [&](const EdgePoint& x, const EdgePoint& y) { return (y.t - x.t) <= margin; }),
                  out.end());
    };
    std::vector<glm::uvec3> triangles;
    std::vector<std::uint32_t> triangle_patch;
    triangles.reserve(display.triangles.size());
    triangle_patch.reserve(display.triangles.size());
    std::array<std::vector<EdgePoint>, 3> on_edge;
    std::vector<std::uint32_t> loop;
    const std::size_t original = display.triangles.size();
    for (std::size_t t = 0; t < original; ++t) {
        const glm::uvec3 c = display.triangles[t];
        bool split = false;
        for (int k = 0; k < 3; ++k) {
            on_edge[k].clear();
            if (open[3 * t + k]) inside(c[k], c[(k + 1) % 3], on_edge[k]);
            split = split || !on_edge[k].empty();
        }
        if (!split) {
            triangles.push_back(c);
            triangle_patch.push_back(display.triangle_patch[t]);
            continue;
        }
        loop.clear();
        for (int k = 0; k < 3; ++k) {
            loop.push_back(c[k]);
            for (const EdgePoint& p : on_edge[k]) {
                const std::pair<std::uint32_t, double> parts[] = {{c[k], 1.0 - p.t}, {c[(k + 1) % 3], p.t}};
                loop.push_back(add_blended_vertex(display, parts));
            }
        }
        const std::pair<std::uint32_t, double> thirds[] = {
            {c[0], 1.0 / 3.0}, {c[1], 1.0 / 3.0}, {c[2], 1.0 / 3.0}};
        const std::uint32_t centre = add_blended_vertex(display, thirds);
        for (std::size_t k = 0; k < loop.size(); ++k) {
            triangles.emplace_back(centre, loop[k], loop[(k + 1) % loop.size()]);
            triangle_patch.push_back(display.triangle_patch[t]);
        }
    }
    display.triangles = std::move(triangles);
    display.triangle_patch = std::move(triangle_patch);
}

}  // namespace rad
