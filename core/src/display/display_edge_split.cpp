#include "display/display_edge_split.hpp"

#include <glm/geometric.hpp>
#include <stdexcept>
#include <unordered_map>

namespace rad {

namespace {

std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

// The new vertex halfway along a -> b.
void append_midpoint(DisplayMesh& d, std::uint32_t a, std::uint32_t b) {
    d.positions.push_back(0.5f * (d.positions[a] + d.positions[b]));
    const glm::vec3 n = d.normals[a] + d.normals[b];
    d.normals.push_back(glm::length(n) > 0.0f ? glm::normalize(n) : d.normals[a]);
    if (!d.texcoords.empty()) d.texcoords.push_back(0.5f * (d.texcoords[a] + d.texcoords[b]));
    const std::size_t first = d.weight_patch.size();
    for (const std::uint32_t v : {a, b}) {
        for (std::uint32_t k = d.weight_begin[v]; k < d.weight_begin[v + 1]; ++k) {
            std::size_t at = first;
            while (at < d.weight_patch.size() && d.weight_patch[at] != d.weight_patch[k]) ++at;
            if (at == d.weight_patch.size()) {
                d.weight_patch.push_back(d.weight_patch[k]);
                d.weight.push_back(0.0f);
            }
            d.weight[at] += 0.5f * d.weight[k];
        }
    }
    d.weight_begin.push_back(static_cast<std::uint32_t>(d.weight_patch.size()));
}

// Appends the pieces of triangle (c0, c1, c2), whose edges c0c1, c1c2, c2c0 have midpoints m[0..2]
// (kNone where not split), counter-clockwise as the triangle was.
constexpr std::uint32_t kNone = 0xffffffffu;
void append_pieces(const glm::uvec3& c, const std::uint32_t m[3], std::vector<glm::uvec3>& out) {
    const int splits = (m[0] != kNone) + (m[1] != kNone) + (m[2] != kNone);
    if (splits == 0) {
        out.push_back(c);
        return;
    }
    if (splits == 3) {
        out.push_back({c[0], m[0], m[2]});
        out.push_back({m[0], c[1], m[1]});
        out.push_back({m[2], m[1], c[2]});
        out.push_back({m[0], m[1], m[2]});
        return;
    }
    // Rotate so the (first) split edge is c0c1.
    int r = 0;
    if (splits == 1) {
        while (m[r] == kNone) ++r;
    } else {
        while (m[(r + 2) % 3] != kNone) ++r;  // the unsplit edge becomes c2c0
    }
    const std::uint32_t a = c[r], b = c[(r + 1) % 3], e = c[(r + 2) % 3];
    const std::uint32_t ab = m[r], be = m[(r + 1) % 3];
    if (splits == 1) {
        out.push_back({a, ab, e});
        out.push_back({ab, b, e});
        return;
    }
    out.push_back({ab, b, be});
    out.push_back({a, ab, be});
    out.push_back({a, be, e});
}

}  // namespace

std::vector<DisplayEdge> interior_edges(const DisplayMesh& display) {
    std::unordered_map<std::uint64_t, int> uses;
    uses.reserve(display.triangles.size() * 3);
    for (const glm::uvec3& t : display.triangles)
        for (int k = 0; k < 3; ++k) ++uses[edge_key(t[k], t[(k + 1) % 3])];
    std::vector<DisplayEdge> edges;
    for (const glm::uvec3& t : display.triangles) {
        for (int k = 0; k < 3; ++k) {
            const auto it = uses.find(edge_key(t[k], t[(k + 1) % 3]));
            if (it->second != 2) continue;
            it->second = 0;  // listed
            edges.push_back({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
        }
    }
    return edges;
}

std::size_t split_display_edges(DisplayMesh& display, std::span<const DisplayEdge> edges) {
    if (!display.traced.direct_irradiance.empty() || !display.traced.gather.empty() ||
        !display.light.direct.vertex.empty())
        throw std::invalid_argument("split_display_edges: the mesh's vertex light is already made");
    const std::size_t first = display.vertex_count();
    std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
    midpoint.reserve(edges.size());
    for (const DisplayEdge& e : edges) {
        if (!midpoint.emplace(edge_key(e.a, e.b), static_cast<std::uint32_t>(display.vertex_count())).second)
            continue;
        append_midpoint(display, e.a, e.b);
    }
    std::vector<glm::uvec3> triangles;
    std::vector<std::uint32_t> patch;
    std::vector<std::uint32_t> start(display.triangles.size() + 1, 0);  // each old triangle's first piece
    triangles.reserve(display.triangles.size() + 3 * edges.size());
    for (std::size_t t = 0; t < display.triangles.size(); ++t) {
        const glm::uvec3& c = display.triangles[t];
        std::uint32_t m[3];
        for (int k = 0; k < 3; ++k) {
            const auto it = midpoint.find(edge_key(c[k], c[(k + 1) % 3]));
            m[k] = it == midpoint.end() ? kNone : it->second;
        }
        start[t] = static_cast<std::uint32_t>(triangles.size());
        append_pieces(c, m, triangles);
        patch.resize(triangles.size(), display.triangle_patch[t]);
    }
    start.back() = static_cast<std::uint32_t>(triangles.size());
    for (DisplayMesh::TexturedRange& range : display.textured) {
        const std::uint32_t end = start[range.first_triangle + range.triangle_count];
        range.first_triangle = start[range.first_triangle];
        range.triangle_count = end - range.first_triangle;
    }
    display.triangles = std::move(triangles);
    display.triangle_patch = std::move(patch);
    return first;
}

}  // namespace rad
