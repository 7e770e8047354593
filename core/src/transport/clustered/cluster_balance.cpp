#include "transport/clustered/cluster_balance.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "ray/coverage.hpp"
#include "ray/ray_offset.hpp"
#include "sampling/sampling.hpp"
#include "transport/clustered/cluster_flow.hpp"
#include "transport/clustered/cluster_geometry.hpp"
#include "transport/pooled_reach.hpp"

namespace rad {

namespace {

// Σ_k T_rk v_k for every leaf r (the unscaled gather, one channel).
void gather_channel(const ClusterHierarchy& h, std::span<const double> v, std::vector<double>& out) {
    std::vector<glm::dvec3> values(v.size()), gathered(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) values[k] = glm::dvec3(v[k]);
    FlowBuffers buffers;
    gather_leaves(h, values, gathered, false, buffers);
    out.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k) out[k] = gathered[k].x;
}

// Points per leaf that probe for a closed object standing on it.
constexpr int kLeafCoverageProbes = 32;

// Leaves pooled until their rays measure the links' bias to a few per cent.
constexpr std::size_t kPoolLeaves = 16;

// Per base patch, its leaves (indices into h.leaves).
std::vector<std::vector<std::uint32_t>> leaves_by_base_patch(const ClusterHierarchy& h) {
    std::vector<std::vector<std::uint32_t>> leaves(h.tree.base_size());
    for (std::size_t k = 0; k < h.leaves.size(); ++k)
        leaves[h.tree[h.leaves[k]].base_patch].push_back(static_cast<std::uint32_t>(k));
    return leaves;
}

// Per leaf, the ratio of measured reach to the links' row sum over a pool of leaves around it
// (pooled_ratio): its base patch when that has kPoolLeaves leaves, else the smallest cluster above it that
// has. The links' error varies slowly over the scene; one leaf's 64 rays are too noisy to correct it alone.
std::vector<double> pooled_bias(const ClusterHierarchy& h, std::span<const double> links) {
    const std::vector<std::vector<std::uint32_t>> leaves_of = leaves_by_base_patch(h);
    std::vector<std::size_t> leaf_count(h.clusters.size(), 0);
    std::vector<std::uint32_t> parent(h.clusters.size(), 0), patch_cluster(h.tree.base_size(), 0);
    for (std::size_t c = h.clusters.size(); c-- > 0;) {
        const ClusterHierarchy::Cluster& node = h.clusters[c];
        for (std::uint32_t k = 0; k < node.child_count; ++k)
            parent[node.first_child + k] = static_cast<std::uint32_t>(c);
        for (std::uint32_t k = node.patch_begin; k < node.patch_end; ++k) {
            leaf_count[c] += leaves_of[h.patch_order[k]].size();
            if (node.child_count == 0) patch_cluster[h.patch_order[k]] = static_cast<std::uint32_t>(c);
        }
    }
    std::vector<PoolLeaf> pool;
    const auto add_patch = [&](std::uint32_t p) {
        for (const std::uint32_t k : leaves_of[p])
            pool.push_back({h.tree[h.leaves[k]].shape.area, links[k], static_cast<double>(h.reach[k])});
    };
    std::vector<double> cluster_ratio(h.clusters.size(), -1.0);  // -1: not yet computed
    std::vector<double> bias(h.leaves.size(), 1.0);
    for (std::uint32_t p = 0; p < h.tree.base_size(); ++p) {
        double ratio = 0.0;
        if (leaves_of[p].size() >= kPoolLeaves) {
            pool.clear();
            add_patch(p);
            ratio = pooled_ratio(pool);
        } else {
            std::uint32_t c = patch_cluster[p];
            while (c != 0 && leaf_count[c] < kPoolLeaves) c = parent[c];
            if (cluster_ratio[c] < 0.0) {
                pool.clear();
                for (std::uint32_t k = h.clusters[c].patch_begin; k < h.clusters[c].patch_end; ++k)
                    add_patch(h.patch_order[k]);
                cluster_ratio[c] = pooled_ratio(pool);
            }
            ratio = cluster_ratio[c];
        }
        for (const std::uint32_t k : leaves_of[p]) bias[k] = ratio;
    }
    return bias;
}

// Per leaf, the reach of its exposed part: the links' row sum corrected by the pooled bias, then moved
// towards the leaf's own measurement by what exceeds twice its standard error (a closed scene's rays all
// arrive: exactly 1), over the exposed share (the links and the measurement both count the covered part as
// blocked); for an emitter's leaves, what its direct light delivers.
std::vector<double> reach_targets(const ClusterHierarchy& h) {
    const std::size_t n = h.leaves.size();
    std::vector<double> links;
    gather_channel(h, std::vector<double>(n, 1.0), links);
    const std::vector<double> bias = pooled_bias(h, links);
    std::vector<double> target(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
        const double measured = h.reach[k];
        if (!(links[k] > 0.0) || measured == 0.0) continue;  // covered, or seeing nothing
        const double prior = std::min(1.0, links[k] * bias[k]);
        const double noise = std::sqrt(measured * (1.0 - measured) / kReachRays);
        const double excess = std::max(0.0, std::abs(measured - prior) - 2.0 * noise);
        const double whole = prior + std::copysign(excess, measured - prior);
        target[k] = h.exposed[k] > 0.0f ? std::min(1.0, whole / static_cast<double>(h.exposed[k])) : 0.0;
    }
    // An emitter's leaves send their emission by the direct light's column: their links reach as far.
    if (!h.direct.empty())
        for (std::size_t k = 0; k < n; ++k)
            if (const std::uint32_t c = h.direct.leaf_column[k]; c != ClusterHierarchy::DirectLight::kNone)
                target[k] = static_cast<double>(h.direct.share[c]);
    return target;
}

}  // namespace

double exposed_area(const ClusterHierarchy& h, std::size_t leaf) {
    return h.tree[h.leaves[leaf]].shape.area * static_cast<double>(h.exposed[leaf]);
}

void measure_reach(ClusterHierarchy& h, const RayScene& rays, double offset, double contact,
                   std::uint64_t seed) {
    h.reach.assign(h.leaves.size(), 1.0f);
    h.exposed.assign(h.leaves.size(), 1.0f);
    h.escape.assign(h.leaves.size(), 0.0f);
    tbb::parallel_for(std::size_t(0), h.leaves.size(), [&](std::size_t k) {
        const std::uint32_t e = h.leaves[k];
        const Element& element = h.tree[e];
        const ConvexPolygon polygon = element_polygon(h.tree, e);
        RandomStream random(seed ^ 0x636c7573ull, e);
        std::vector<glm::dvec2> origins(kReachRays), directions(kReachRays);
        stratified_square(random, origins);
        stratified_square(random, directions);
        const Frame frame = frame_around(element.shape.normal);
        std::vector<Ray> batch(kReachRays);
        for (std::size_t i = 0; i < kReachRays; ++i)
            batch[i] =
                Ray{point_on_convex_polygon(polygon.span(), origins[i]) + offset * element.shape.normal, 0.0f,
                    frame.to_world(cosine_direction(directions[i])), 1e30f};
        std::vector<RayHit> hits(kReachRays);
        rays.intersect(batch, hits);
        std::size_t reached = 0, covered = 0, back = 0, missed = 0;
        for (const RayHit& hit : hits) {
            if (hit.patch == RayHit::kBackFace) ++back;
            if (hit.patch == RayHit::kMissed) ++missed;
            if (hit.patch >= RayHit::kBackFace) continue;
            const bool head_on = glm::dot(h.tree[hit.patch].shape.normal, element.shape.normal) < -0.99;
            if (head_on && static_cast<double>(hit.t) < contact) {
                ++covered;
            } else {
                ++reached;
            }
        }
        h.reach[k] = static_cast<float>(static_cast<double>(reached) / kReachRays);
        // Rays that meet back faces may start inside a closed object standing on the leaf (a box without a
        // bottom): the coverage probes tell.
        const double inside = back > 0 ? covered_share(polygon.span(), element.shape.normal, rays, seed, e,
                                                       offset, kLeafCoverageProbes)
                                       : 0.0;
        h.exposed[k] =
            static_cast<float>(std::max(0.0, 1.0 - inside - static_cast<double>(covered) / kReachRays));
        // Rays that meet nothing leave from exposed points: per unit of the exposed part.
        if (h.exposed[k] > 0.0f)
            h.escape[k] =
                static_cast<float>(std::min(1.0, static_cast<double>(missed) / kReachRays / h.exposed[k]));
    });
}

double balance_leaves(ClusterHierarchy& h) {
    const std::size_t n = h.leaves.size();
    const std::vector<double> target = reach_targets(h);
    std::vector<double> area(n);
    for (std::size_t k = 0; k < n; ++k) area[k] = exposed_area(h, k);
    const LeafScales scales = balance_rows_and_columns(
        target, area,
        [&](std::span<const double> send, std::vector<double>& rows) { gather_channel(h, send, rows); },
        [&](std::span<const double> weights, std::span<double> columns) { spread(h, weights, columns); });
    h.receive_scale.assign(scales.receive.begin(), scales.receive.end());
    h.send_scale.assign(scales.send.begin(), scales.send.end());
    return scales.error;
}

}  // namespace rad
