#include "transport/clustered/cluster_shadow_split.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <vector>

#include "sampling/patch_shapes.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

constexpr int kPoints = 5;          // per element: its centroid and its corners drawn a tenth of the way in
constexpr int kTestedEmitters = 8;  // per leaf: the brightest in its view

std::array<glm::dvec3, kPoints> sample_points(const ElementTree& tree, std::uint32_t e, double offset) {
    const Element& element = tree[e];
    const glm::dvec3 c = element.shape.centroid;
    const glm::dvec3 lift = offset * element.shape.normal;
    std::array<glm::dvec3, kPoints> points;
    points[0] = c + lift;
    for (int i = 0; i < 4; ++i) points[1 + i] = c + 0.9 * (tree.points()[element.corners[i]] - c) + lift;
    return points;
}

// The error bound of one emitter at one leaf without regard to its visibility: ρ E F.
struct Candidate {
    std::uint32_t emitter = 0;  // into the emitters
    double bound = 0.0;
};

// The leaf's emitters whose unoccluded light could leave more than `threshold`, brightest first.
std::vector<Candidate> bright_emitters(const ClusterHierarchy& h, std::uint32_t e,
                                       std::span<const PatchShape> shapes, std::span<const double> emitted,
                                       double threshold) {
    const Element& leaf = h.tree[e];
    const double rho = luminance(h.reflectance[e]);
    const double radius = 0.5 * h.tree.longest_edge(e);
    std::vector<Candidate> out;
    for (std::uint32_t c = 0; c < shapes.size(); ++c) {
        if (glm::dot(shapes[c].centroid - leaf.shape.centroid, leaf.shape.normal) <= 0.0) continue;
        const double bound =
            rho * emitted[c] * factor_weight(leaf.shape.centroid, leaf.shape.normal, radius, shapes[c]);
        if (bound > threshold) out.push_back({c, bound});
    }
    std::sort(out.begin(), out.end(),
              [](const Candidate& a, const Candidate& b) { return a.bound > b.bound; });
    if (out.size() > kTestedEmitters) out.resize(kTestedEmitters);
    return out;
}

// Whether an emitter's visible share changes across the leaf by enough to leave more than `threshold`.
bool shadow_edge_crosses(const ClusterHierarchy& h, std::uint32_t e, std::span<const std::uint32_t> emitters,
                         std::span<const Candidate> candidates, const RayScene& rays, double offset,
                         double threshold, std::vector<Ray>& batch, std::vector<std::uint8_t>& blocked) {
    const std::array<glm::dvec3, kPoints> from = sample_points(h.tree, e, offset);
    for (const Candidate& candidate : candidates) {
        const std::array<glm::dvec3, kPoints> to = sample_points(h.tree, emitters[candidate.emitter], offset);
        batch.clear();
        for (const glm::dvec3& a : from)
            for (const glm::dvec3& b : to) batch.push_back({a, 0.0f, b - a, 0.999f});
        blocked.resize(batch.size());
        rays.occluded(batch, blocked);
        int fewest = kPoints, most = 0;
        for (int i = 0; i < kPoints; ++i) {
            int seen = 0;
            for (int j = 0; j < kPoints; ++j) seen += blocked[i * kPoints + j] ? 0 : 1;
            fewest = std::min(fewest, seen);
            most = std::max(most, seen);
        }
        if (candidate.bound * (most - fewest) / kPoints > threshold) return true;
    }
    return false;
}

}  // namespace

std::size_t split_shadow_edges(ClusterHierarchy& h, const PatchMesh& base,
                               std::span<const std::uint32_t> emitters, const RayScene& rays, double offset,
                               double min_patch_size, double threshold, std::size_t max_new_leaves) {
    h.leaves = h.tree.leaves();
    if (emitters.empty() || !(threshold > 0.0)) return 0;
    std::vector<PatchShape> shapes;
    std::vector<double> emitted;
    std::vector<std::uint8_t> is_emitter(h.tree.base_size(), 0);
    for (std::uint32_t p : emitters) {
        shapes.push_back(patch_shape(base, p));
        emitted.push_back(luminance(h.emission[p]));
        is_emitter[p] = 1;
    }
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t e : h.leaves)
        if (!is_emitter[h.tree[e].base_patch] && h.tree.longest_edge(e) > 2.0 * min_patch_size)
            candidates.push_back(e);
    std::size_t splits = 0;
    while (!candidates.empty() && 3 * splits < max_new_leaves) {
        std::vector<std::uint8_t> split(candidates.size(), 0);
        tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) {
            thread_local std::vector<Ray> batch;
            thread_local std::vector<std::uint8_t> blocked;
            const std::vector<Candidate> bright =
                bright_emitters(h, candidates[i], shapes, emitted, threshold);
            split[i] = shadow_edge_crosses(h, candidates[i], emitters, bright, rays, offset, threshold, batch,
                                           blocked);
        });
        std::vector<std::uint32_t> next;
        for (std::size_t i = 0; i < candidates.size() && 3 * splits < max_new_leaves; ++i) {
            if (!split[i]) continue;
            const std::uint32_t e = candidates[i];
            const std::uint32_t first = h.tree.split(e);
            for (int k = 0; k < 4; ++k) {
                h.reflectance.push_back(h.reflectance[e]);
                h.emission.push_back(h.emission[e]);
            }
            ++splits;
            for (std::uint32_t k = 0; k < 4; ++k)
                if (h.tree.longest_edge(first + k) > 2.0 * min_patch_size) next.push_back(first + k);
        }
        candidates = std::move(next);
    }
    h.leaves = h.tree.leaves();
    return splits;
}

}  // namespace rad
