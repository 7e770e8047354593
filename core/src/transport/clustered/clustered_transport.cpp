// The cluster hierarchy as a Transport: built over the base patches' boxes, refined from the root's link to
// itself, and gathered with pull, links and push through clusters and elements.
#include "rad/transport/clustered/clustered_transport.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rad/ray/box_tree.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/util/error.hpp"
#include "rad/util/stopwatch.hpp"
#include "sampling/sampling.hpp"
#include "transport/clustered/cluster_geometry.hpp"
#include "transport/clustered/clustered_refine.hpp"
#include "transport/refinement_settings.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"

namespace rad {

namespace {

// Rays per leaf that measure its form factor to the whole scene.
constexpr std::size_t kReachRays = 64;

Box patch_box(const PatchMesh& base, std::uint32_t p) {
    Box box{base.points[base.corners[p][0]], base.points[base.corners[p][0]]};
    for (int k = 1; k < 4; ++k) {
        box.lower = glm::min(box.lower, base.points[base.corners[p][k]]);
        box.upper = glm::max(box.upper, base.points[base.corners[p][k]]);
    }
    return box;
}

void build_clusters(const PatchMesh& base, unsigned leaf_size, ClusterHierarchy& h) {
    std::vector<Box> boxes(base.size());
    for (std::uint32_t p = 0; p < base.size(); ++p) boxes[p] = patch_box(base, p);
    const BoxTree tree = build_box_tree(boxes, leaf_size);
    h.patch_order = tree.items;
    h.clusters.resize(tree.nodes.size());
    for (std::size_t c = 0; c < tree.nodes.size(); ++c) {
        const BoxTree::Node& node = tree.nodes[c];
        ClusterHierarchy::Cluster& cluster = h.clusters[c];
        cluster.centre = 0.5 * (node.bounds.lower + node.bounds.upper);
        cluster.radius = 0.5 * glm::length(node.bounds.upper - node.bounds.lower);
        cluster.first_child = node.leaf ? 0 : node.first;
        cluster.child_count = node.leaf ? 0 : node.count;
        cluster.patch_begin = node.item_begin;
        cluster.patch_end = node.item_end;
        for (std::uint32_t k = node.item_begin; k < node.item_end; ++k) {
            const Patch& patch = base.patches[tree.items[k]];
            cluster.area += patch.area;
            for (int axis = 0; axis < 3; ++axis) {
                cluster.facing[2 * axis] += patch.area * std::max(0.0, patch.normal[axis]);
                cluster.facing[2 * axis + 1] += patch.area * std::max(0.0, -patch.normal[axis]);
            }
        }
    }
}

// Per element and per cluster, the mean radiosity over its area, from the leaves' (children come after
// their parents in both trees).
struct NodeValues {
    std::vector<glm::dvec3> element;
    std::vector<glm::dvec3> cluster;
};

// What a cluster receives, by the direction it comes from: per axis direction (+x, −x, +y, −y, +z, −z),
// the irradiance a surface facing that way takes (ClusterLink).
using DirectionalIrradiance = std::array<glm::dvec3, 6>;

struct Irradiance {
    std::vector<glm::dvec3> element;
    std::vector<DirectionalIrradiance> cluster;
};

void add_directional(DirectionalIrradiance& into, const glm::vec3& direction, const glm::dvec3& value) {
    for (int a = 0; a < 3; ++a)
        into[2 * a + (direction[a] >= 0.0f ? 0 : 1)] += std::abs(static_cast<double>(direction[a])) * value;
}

// What a surface of normal n inside the cluster takes of it.
glm::dvec3 taken_by(const DirectionalIrradiance& h, const glm::dvec3& n) {
    glm::dvec3 sum(0.0);
    for (int a = 0; a < 3; ++a) sum += std::max(0.0, n[a]) * h[2 * a] + std::max(0.0, -n[a]) * h[2 * a + 1];
    return sum;
}

void pull(const ClusterHierarchy& h, std::span<const glm::dvec3> leaf_values, NodeValues& b) {
    b.element.assign(h.tree.size(), glm::dvec3(0.0));
    for (std::size_t k = 0; k < h.leaves.size(); ++k) b.element[h.leaves[k]] = leaf_values[k];
    for (std::size_t e = h.tree.size(); e-- > 0;) {
        const Element& element = h.tree[e];
        if (element.is_leaf()) continue;
        glm::dvec3 sum(0.0);
        double area = 0.0;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c) {
            sum += h.tree[c].shape.area * b.element[c];
            area += h.tree[c].shape.area;
        }
        b.element[e] = area > 0.0 ? sum / area : glm::dvec3(0.0);
    }
    b.cluster.assign(h.clusters.size(), glm::dvec3(0.0));
    for (std::size_t c = h.clusters.size(); c-- > 0;) {
        const ClusterHierarchy::Cluster& cluster = h.clusters[c];
        glm::dvec3 sum(0.0);
        if (cluster.child_count > 0) {
            for (std::uint32_t k = 0; k < cluster.child_count; ++k)
                sum += h.clusters[cluster.first_child + k].area * b.cluster[cluster.first_child + k];
        } else {
            for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k)
                sum += h.tree[h.patch_order[k]].shape.area * b.element[h.patch_order[k]];
        }
        b.cluster[c] = cluster.area > 0.0 ? sum / cluster.area : glm::dvec3(0.0);
    }
}

const glm::dvec3& value_of(const NodeValues& v, std::uint32_t node) {
    return ClusterNode::is_cluster(node) ? v.cluster[ClusterNode::index(node)]
                                         : v.element[ClusterNode::index(node)];
}

// Irradiance gathered along the links into each receiver, then pushed down: a cluster's to its children
// (each surface taking it by its orientation), an element's to its quarters.
void gather_push(const ClusterHierarchy& h, const NodeValues& b, Irradiance& irradiance) {
    irradiance.element.assign(h.tree.size(), glm::dvec3(0.0));
    irradiance.cluster.assign(h.clusters.size(), DirectionalIrradiance{});
    const std::size_t runs = h.receiver_runs.empty() ? 0 : h.receiver_runs.size() - 1;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, runs, 256), [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t k = range.begin(); k < range.end(); ++k) {
                const std::uint32_t receiver = h.links[h.receiver_runs[k]].receiver;
                if (ClusterNode::is_cluster(receiver)) {
                    DirectionalIrradiance sum{};
                    for (std::uint32_t l = h.receiver_runs[k]; l < h.receiver_runs[k + 1]; ++l)
                        add_directional(
                            sum, h.links[l].direction,
                            static_cast<double>(h.links[l].factor) * value_of(b, h.links[l].source));
                    irradiance.cluster[ClusterNode::index(receiver)] = sum;
                } else {
                    glm::dvec3 sum(0.0);
                    for (std::uint32_t l = h.receiver_runs[k]; l < h.receiver_runs[k + 1]; ++l)
                        sum += static_cast<double>(h.links[l].factor) * value_of(b, h.links[l].source);
                    irradiance.element[receiver] = sum;
                }
            }
        });
    for (std::size_t c = 0; c < h.clusters.size(); ++c) {
        const ClusterHierarchy::Cluster& cluster = h.clusters[c];
        const DirectionalIrradiance above = irradiance.cluster[c];
        if (cluster.child_count > 0) {
            for (std::uint32_t k = 0; k < cluster.child_count; ++k)
                for (int d = 0; d < 6; ++d) irradiance.cluster[cluster.first_child + k][d] += above[d];
        } else {
            for (std::uint32_t k = cluster.patch_begin; k < cluster.patch_end; ++k) {
                const std::uint32_t p = h.patch_order[k];
                irradiance.element[p] += taken_by(above, h.tree[p].shape.normal);
            }
        }
    }
    for (std::size_t e = 0; e < h.tree.size(); ++e) {
        const Element& element = h.tree[e];
        if (element.is_leaf()) continue;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            irradiance.element[c] += irradiance.element[e];
    }
}

void index_links(ClusterHierarchy& h) {
    std::sort(h.links.begin(), h.links.end(), [](const ClusterLink& a, const ClusterLink& b) {
        return a.receiver != b.receiver ? a.receiver < b.receiver : a.source < b.source;
    });
    h.receiver_runs.clear();
    for (std::size_t l = 0; l < h.links.size(); ++l)
        if (l == 0 || h.links[l].receiver != h.links[l - 1].receiver)
            h.receiver_runs.push_back(static_cast<std::uint32_t>(l));
    h.receiver_runs.push_back(static_cast<std::uint32_t>(h.links.size()));
}

// The share of cosine-weighted rays from each leaf that meet the front of a surface: its form factor to the
// whole scene. A surface lying on another face to face (a box's bottom on a floor, the floor under it) is
// covered there: its rays meet the other within `contact`, head on, and count as blocked.
void measure_reach(ClusterHierarchy& h, const RayScene& rays, double offset, double contact,
                   std::uint64_t seed) {
    h.reach.assign(h.tree.size(), 1.0f);
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
        const auto reached = std::count_if(hits.begin(), hits.end(), [&](const RayHit& hit) {
            if (hit.patch >= RayHit::kBackFace) return false;
            const bool head_on = glm::dot(h.tree[hit.patch].shape.normal, element.shape.normal) < -0.99;
            return !(head_on && static_cast<double>(hit.t) < contact);
        });
        h.reach[e] = static_cast<float>(static_cast<double>(reached) / kReachRays);
    });
}

// Scales each leaf's gathered factors towards its measured reach, by what exceeds twice the measurement's
// standard error: a closed scene's leaves (no ray escapes, no noise) then gather exactly 1.
void normalize_leaves(ClusterHierarchy& h) {
    h.leaf_scale.assign(h.tree.size(), 1.0f);
    NodeValues ones;
    Irradiance irradiance;
    pull(h, std::vector<glm::dvec3>(h.leaves.size(), glm::dvec3(1.0)), ones);
    gather_push(h, ones, irradiance);
    for (const std::uint32_t e : h.leaves) {
        const double links = irradiance.element[e].x, measured = h.reach[e];
        if (!(links > 0.0)) continue;
        if (measured == 0.0) {  // wholly covered, or seeing nothing: it gathers nothing
            h.leaf_scale[e] = 0.0f;
            continue;
        }
        const double noise = std::sqrt(measured * (1.0 - measured) / kReachRays);
        const double excess = std::max(0.0, std::abs(measured - links) - 2.0 * noise);
        const double target = links + std::copysign(excess, measured - links);
        h.leaf_scale[e] = static_cast<float>(std::clamp(target / links, 0.0, 4.0));
    }
}

}  // namespace

std::size_t ClusterHierarchy::memory_bytes() const {
    return clusters.capacity() * sizeof(Cluster) + patch_order.capacity() * sizeof(std::uint32_t) +
           tree.memory_bytes() + (reflectance.capacity() + emission.capacity()) * sizeof(glm::dvec3) +
           links.capacity() * sizeof(ClusterLink) + receiver_runs.capacity() * sizeof(std::uint32_t) +
           (leaf_scale.capacity() + reach.capacity()) * sizeof(float) +
           leaves.capacity() * sizeof(std::uint32_t);
}

ClusteredTransport::ClusteredTransport(std::unique_ptr<ClusterHierarchy> hierarchy,
                                       const ClusteredReport& report)
    : hierarchy_(std::move(hierarchy)), report_(report) {
    const ClusterHierarchy& h = *hierarchy_;
    area.resize(h.leaves.size());
    reflectance.resize(h.leaves.size());
    emission.resize(h.leaves.size());
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        area[k] = h.tree[h.leaves[k]].shape.area;
        reflectance[k] = h.reflectance[h.leaves[k]];
        emission[k] = h.emission[h.leaves[k]];
    }
}

void ClusteredTransport::gather(std::span<const glm::dvec3> radiosity,
                                std::span<glm::dvec3> irradiance) const {
    const ClusterHierarchy& h = *hierarchy_;
    // Kept between calls on this thread: a solver steps on one thread.
    thread_local NodeValues b;
    thread_local Irradiance gathered;
    pull(h, radiosity, b);
    gather_push(h, b, gathered);
    for (std::size_t k = 0; k < h.leaves.size(); ++k)
        irradiance[k] = static_cast<double>(h.leaf_scale[h.leaves[k]]) * gathered.element[h.leaves[k]];
}

std::vector<double> ClusteredTransport::reach() const {
    const std::vector<glm::dvec3> ones(size(), glm::dvec3(1.0));
    std::vector<glm::dvec3> gathered(size());
    gather(ones, gathered);
    std::vector<double> out(size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = gathered[k].x;
    return out;
}

TransportReport ClusteredTransport::report() const {
    TransportReport r;
    r.kind = "clustered";
    r.interaction_name = "links";
    r.elements = size();
    r.interactions = report_.links;
    r.memory_bytes = report_.memory_bytes;
    r.rays = report_.rays;
    r.seconds = report_.seconds;
    r.form_factor_passes = 1;
    r.details = {{"base_patches", static_cast<double>(report_.base_patches)},
                 {"clusters", static_cast<double>(report_.clusters)},
                 {"tree_elements", static_cast<double>(report_.elements)},
                 {"leaves", static_cast<double>(report_.leaves)},
                 {"cluster_links", static_cast<double>(report_.cluster_links)},
                 {"min_patch_size", report_.min_patch_size}};
    if (report_.limited) r.notes = "refinement stopped at the link limit";
    return r;
}

std::unique_ptr<ClusteredTransport> make_clustered_transport(const Scene& scene, const PatchMesh& base,
                                                             const ClusteredOptions& options,
                                                             Progress* progress) {
    check_refinement_settings(options.tolerance, options.min_patch_size, options.visibility_rays);
    const Stopwatch clock;
    auto h = std::make_unique<ClusterHierarchy>(base);
    for (const Patch& p : base.patches) {
        const Material& material = scene.surfaces[p.surface].material;
        h->reflectance.push_back(material.reflectance);
        h->emission.push_back(material.emitted_radiosity());
    }
    ClusteredReport report;
    report.base_patches = base.size();
    report.min_patch_size =
        options.min_patch_size > 0.0 ? options.min_patch_size : bounding_box(scene).largest_extent() / 256.0;
    if (progress) progress->begin("clustering", 0);
    build_clusters(base, options.max_cluster_patches, *h);
    const RayScene rays(base);
    const double offset = ray_offset(base);
    if (progress) progress->begin("linking clusters and elements", 0);
    refine_cluster_links(*h, rays, offset, options, report, progress);
    index_links(*h);
    h->leaves = h->tree.leaves();
    h->leaf_patches = h->tree.leaf_mesh(h->leaves);
    // Closer than this is contact: a thousandth of the scene's extent.
    measure_reach(*h, rays, offset, 1e-3 * bounding_box(scene).largest_extent(), options.seed);
    report.rays += h->leaves.size() * kReachRays;
    normalize_leaves(*h);
    report.clusters = h->clusters.size();
    report.elements = h->tree.size();
    report.leaves = h->leaves.size();
    report.links = h->links.size();
    report.memory_bytes = h->memory_bytes();
    report.seconds = clock.seconds();
    return std::make_unique<ClusteredTransport>(std::move(h), report);
}

}  // namespace rad
