#include "transport/adaptive/adaptive_neighbours.hpp"

#include <algorithm>

namespace rad {

namespace {

// (point, patch) for every point on each patch's boundary: its outline, or its corners in a conforming mesh.
std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary_points(const PatchMesh& mesh) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    out.reserve(4 * mesh.size());
    const bool outlined = !mesh.outline_begin.empty();
    for (std::uint32_t q = 0; q < mesh.size(); ++q) {
        if (outlined) {
            for (std::uint32_t k = mesh.outline_begin[q]; k < mesh.outline_begin[q + 1]; ++k)
                out.emplace_back(mesh.outline[k], q);
        } else {
            for (int c = 0; c < mesh.corner_count(q); ++c) out.emplace_back(mesh.corners[q][c], q);
        }
    }
    return out;
}

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> neighbour_pairs(const PatchMesh& mesh) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> points = boundary_points(mesh);
    std::sort(points.begin(), points.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t first = 0; first < points.size();) {
        std::size_t end = first;
        while (end < points.size() && points[end].first == points[first].first) ++end;
        // The patches around one point: a handful, so every pair of them.
        for (std::size_t a = first; a < end; ++a) {
            for (std::size_t b = a + 1; b < end; ++b) {
                const std::uint32_t p = points[a].second, q = points[b].second;
                if (p == q || mesh.patches[p].surface != mesh.patches[q].surface) continue;
                pairs.emplace_back(std::min(p, q), std::max(p, q));
            }
        }
        first = end;
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

}  // namespace rad
