// The cluster hierarchy as a Transport: built over the base patches' boxes, refined from the root's link to
// itself, and gathered with pull, links and push through clusters and elements.
#include "rad/transport/clustered/clustered_transport.hpp"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "rad/ray/box_tree.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/util/error.hpp"
#include "rad/util/stopwatch.hpp"
#include "ray/ray_offset.hpp"
#include "transport/clustered/cluster_balance.hpp"
#include "transport/clustered/cluster_direct_light.hpp"
#include "transport/clustered/cluster_flow.hpp"
#include "transport/clustered/cluster_geometry.hpp"
#include "transport/clustered/cluster_shadow_split.hpp"
#include "transport/clustered/clustered_refine.hpp"
#include "transport/external/outside_light.hpp"
#include "transport/patch_materials.hpp"
#include "transport/refinement_settings.hpp"
#include "transport/uniform/form_factors_memory.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

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
        cluster.lower = node.bounds.lower;
        cluster.upper = node.bounds.upper;
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

void index_links(ClusterHierarchy& h) {
    tbb::parallel_sort(h.links.begin(), h.links.end(), [](const ClusterLink& a, const ClusterLink& b) {
        return a.receiver != b.receiver ? a.receiver < b.receiver : a.source < b.source;
    });
    h.receiver_runs.clear();
    for (std::size_t l = 0; l < h.links.size(); ++l)
        if (l == 0 || h.links[l].receiver != h.links[l - 1].receiver)
            h.receiver_runs.push_back(static_cast<std::uint32_t>(l));
    h.receiver_runs.push_back(static_cast<std::uint32_t>(h.links.size()));
}

// How many leaves the splitting along shadows may add: as many as there are, within what the memory budget
// leaves (a leaf's element, state and row of direct light).
std::size_t shadow_leaf_allowance(const ClusterHierarchy& h, std::size_t budget, std::size_t emitters) {
    const std::size_t per_leaf = kClusteredElementBytes + emitters * 2 * sizeof(float);
    const std::size_t used = h.memory_bytes() + h.leaves.size() * per_leaf;
    const std::size_t room = budget == 0 ? h.leaves.size() : (budget > used ? (budget - used) / per_leaf : 0);
    return std::min(h.leaves.size(), room);
}

// The first round's tolerance, relative to the requested one.
constexpr double kFirstRoundTolerance = 4.0;
// Jacobi steps of the rough solution between the rounds.
constexpr int kRoughSteps = 24;

// A few Jacobi steps over the links as they stand (unbalanced), then the luminance of every node. Where the
// direct light will carry the emitters' light (`aimed`: per base patch), a source's estimate is its
// radiosity less what it emits, so its links are refined for the light it reflects; the scene's mean keeps
// the emission.
RadiosityEstimate rough_solution(const ClusterHierarchy& h, const Scene& scene,
                                 std::span<const std::uint8_t> aimed) {
    const std::size_t n = h.leaves.size();
    std::vector<glm::dvec3> b(n), gathered(n);
    for (std::size_t k = 0; k < n; ++k) b[k] = h.emission[h.leaves[k]];
    FlowBuffers buffers;
    for (int step = 0; step < kRoughSteps; ++step) {
        gather_leaves(h, b, gathered, false, buffers);
        for (std::size_t k = 0; k < n; ++k)
            b[k] = h.emission[h.leaves[k]] + h.reflectance[h.leaves[k]] * gathered[k];
    }
    NodeValues& values = buffers.values;
    pull(h, b, values);
    RadiosityEstimate estimate;
    estimate.mean = h.clusters.empty() ? 0.0 : luminance(values.cluster[0]);
    for (std::size_t k = 0; k < n; ++k) {
        const Element& leaf = h.tree[h.leaves[k]];
        if (aimed[leaf.base_patch]) b[k] -= scene.surfaces[leaf.shape.surface].material.emitted_radiosity();
    }
    pull(h, b, values);
    estimate.element.resize(values.element.size());
    estimate.cluster.resize(values.cluster.size());
    for (std::size_t e = 0; e < values.element.size(); ++e)
        estimate.element[e] = luminance(values.element[e]);
    for (std::size_t c = 0; c < values.cluster.size(); ++c)
        estimate.cluster[c] = luminance(values.cluster[c]);
    return estimate;
}

// The base patches as elements are the least clustering keeps; the links come on top, as refinement finds
// them, up to the budget.
void check_memory(std::size_t base_patches, ClusteredReport& report, const ClusteredOptions& options,
                  Progress* progress) {
    report.memory_budget = memory_budget_bytes(options.max_memory_bytes);
    const std::size_t least = base_patches * kClusteredElementBytes;
    if (report.memory_budget > 0 && least > report.memory_budget) {
        throw MemoryBudgetError("clustering needs at least " + format_bytes(double(least)) + " for " +
                                    std::to_string(base_patches) + " base patches, over the budget of " +
                                    format_bytes(double(report.memory_budget)),
                                least, report.memory_budget, base_patches, 0.0);
    }
    if (progress && report.memory_budget > 0)
        progress->note(std::to_string(base_patches) + " base patches: at least " +
                       format_bytes(double(least)) + ", links as refinement makes them, within " +
                       format_bytes(double(report.memory_budget)));
}

}  // namespace

std::size_t ClusterHierarchy::memory_bytes() const {
    return clusters.capacity() * sizeof(Cluster) + patch_order.capacity() * sizeof(std::uint32_t) +
           tree.memory_bytes() + (reflectance.capacity() + emission.capacity()) * sizeof(glm::dvec3) +
           links.capacity() * sizeof(ClusterLink) + receiver_runs.capacity() * sizeof(std::uint32_t) +
           (receive_scale.capacity() + send_scale.capacity() + reach.capacity() + exposed.capacity() +
            escape.capacity()) *
               sizeof(float) +
           leaves.capacity() * sizeof(std::uint32_t) + direct.factors.memory_bytes() +
           (direct.emitters.capacity() + direct.leaf_column.capacity()) * sizeof(std::uint32_t) +
           direct.share.capacity() * sizeof(float);
}

ClusteredTransport::ClusteredTransport(std::unique_ptr<ClusterHierarchy> hierarchy,
                                       const ClusteredReport& report)
    : hierarchy_(std::move(hierarchy)), report_(report) {
    const ClusterHierarchy& h = *hierarchy_;
    area.resize(h.leaves.size());
    reflectance.resize(h.leaves.size());
    emission.resize(h.leaves.size());
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        // Only the exposed part emits, absorbs and reflects; an area of 0 would be refused.
        area[k] = std::max(exposed_area(h, k), 1e-6 * h.tree[h.leaves[k]].shape.area);
        reflectance[k] = h.reflectance[h.leaves[k]];
        emission[k] = h.emission[h.leaves[k]];
    }
}

void ClusteredTransport::gather(std::span<const glm::dvec3> radiosity,
                                std::span<glm::dvec3> irradiance) const {
    const ClusterHierarchy& h = *hierarchy_;
    // Kept between calls on this thread: a solver steps on one thread.
    thread_local FlowBuffers buffers;
    if (h.direct.empty()) {
        gather_leaves(h, radiosity, irradiance, true, buffers);
        return;
    }
    // The links carry what each leaf reflects; the emitters' light arrives by the direct light's factors.
    thread_local std::vector<glm::dvec3> emitted, reflected;
    emitted.resize(size());
    reflected.resize(size());
    direct_emission(h, emission, reflectance, outside, emitted);
    for (std::size_t k = 0; k < size(); ++k) reflected[k] = radiosity[k] - emitted[k];
    gather_leaves(h, reflected, irradiance, true, buffers);
    add_direct_light(h, emitted, irradiance);
}

std::vector<double> ClusteredTransport::reach() const {
    // The links' row sums, but an emitter's leaves send their emission, nearly all of their radiosity, by
    // the direct light's column: its share. Their links are balanced to the same share where they reach
    // that far (an emitter that reflects nothing has none).
    const ClusterHierarchy& h = *hierarchy_;
    const std::vector<glm::dvec3> ones(size(), glm::dvec3(1.0));
    std::vector<glm::dvec3> gathered(size());
    FlowBuffers buffers;
    gather_leaves(h, ones, gathered, true, buffers);
    std::vector<double> out(size());
    for (std::size_t k = 0; k < out.size(); ++k) {
        const std::uint32_t c =
            h.direct.empty() ? ClusterHierarchy::DirectLight::kNone : h.direct.leaf_column[k];
        out[k] = c == ClusterHierarchy::DirectLight::kNone ? gathered[k].x
                                                           : static_cast<double>(h.direct.share[c]);
    }
    return out;
}

std::vector<double> ClusteredTransport::escape() const {
    const ClusterHierarchy& h = *hierarchy_;
    if (h.escape.size() != size()) return Transport::escape();
    // What does not reach a front (1 − reach) meets a back as often as the leaf's rays found (those rays
    // are counted apart and not scaled); the rest escapes. Taking the leaf's measured escape instead would
    // split the difference between its reach and its measure at random between the escape and the backs.
    // Where no ray escapes (a closed scene), nothing does.
    const std::vector<double> reached = reach();
    std::vector<double> out(size(), 0.0);
    for (std::size_t k = 0; k < out.size(); ++k) {
        const double escape = static_cast<double>(h.escape[k]);
        const double exposed = static_cast<double>(h.exposed[k]);
        if (!(escape > 0.0) || !(exposed > 0.0)) continue;
        const double front = std::min(1.0, static_cast<double>(h.reach[k]) / exposed);
        const double back = std::max(0.0, 1.0 - front - escape);
        out[k] = std::clamp(1.0 - reached[k] - back, 0.0, std::max(0.0, 1.0 - reached[k]));
    }
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
    if (report_.memory_limited)
        r.notes = "refinement stopped at the memory budget (" + format_bytes(double(report_.memory_budget)) +
                  "): a larger budget refines further";
    return r;
}

std::unique_ptr<ClusteredTransport> make_clustered_transport(const Scene& scene, const PatchMesh& base,
                                                             const ClusteredOptions& options,
                                                             Progress* progress) {
    check_refinement_settings(options.tolerance, options.min_patch_size, options.visibility_rays);
    const Stopwatch clock;
    auto h = std::make_unique<ClusterHierarchy>(base);
    h->isotropic = options.isotropic_clusters;
    append_patch_materials(scene, base, h->reflectance, h->emission);
    ClusteredReport report;
    report.base_patches = base.size();
    report.min_patch_size = options.min_patch_size > 0.0
                                ? options.min_patch_size
                                : bounding_box(scene).largest_extent() / kClusteredMinPatchFraction;
    check_memory(base.size(), report, options, progress);
    if (progress) progress->begin("clustering", 0);
    build_clusters(base, options.max_cluster_patches, *h);
    const RayScene rays(base);
    add_outside_light(scene, base, rays, options.seed, {}, h->reflectance, h->emission, progress);
    const double offset = ray_offset(base);
    // Closer than this is contact: a thousandth of the scene's extent.
    const double contact = 1e-3 * bounding_box(scene).largest_extent();
    // Where the emitters are few and small, their light is aimed at every leaf, not linked.
    std::vector<std::uint32_t> emitters = direct_light_emitters(scene, base);
    auto link = [&](const ClusteredOptions& round, const RadiosityEstimate* estimate) {
        h->links.clear();
        report.cluster_links = 0;
        refine_cluster_links(*h, rays, offset, round, report, progress, estimate);
        if (progress) progress->begin("sorting the links", 0);
        index_links(*h);
        h->leaves = h->tree.leaves();
        if (!estimate) return;  // the first guess: its links as they stand are close enough
        if (progress) progress->begin("splitting along shadows", 0);
        split_shadow_edges(*h, base, emitters, rays, offset, report.min_patch_size,
                           round.tolerance * estimate->mean,
                           shadow_leaf_allowance(*h, report.memory_budget, emitters.size()));
        if (progress) progress->begin("reach of the leaves", 0);
        measure_reach(*h, rays, offset, contact, options.seed);
        h->leaf_patches = h->tree.leaf_mesh(h->leaves);
        compute_direct_light(*h, scene, base, emitters, rays, offset, options.direct_light_rays, options.seed,
                             progress);
        report.rays += h->direct.rays;
        if (progress) progress->begin("balancing the leaves' energy", 0);
        report.rays += h->leaves.size() * kReachRays;
        report.balance_error = balance_leaves(*h);
    };
    // Two rounds: the first, coarse, guesses each source's radiosity from the emission; its rough solution
    // tells the second which sources are bright (a floor under the light, say, that lights the ceiling).
    if (progress) progress->begin("refining links (first guess)", 0);
    ClusteredOptions coarse = options;
    coarse.tolerance = kFirstRoundTolerance * options.tolerance;
    coarse.visibility_rays = 1;
    link(coarse, nullptr);
    std::vector<std::uint8_t> aimed(base.size(), 0);
    for (std::uint32_t p : emitters) aimed[p] = 1;
    const RadiosityEstimate estimate = rough_solution(*h, scene, aimed);
    if (progress) progress->begin("refining links", 0);
    link(options, &estimate);
    report.clusters = h->clusters.size();
    report.elements = h->tree.size();
    report.leaves = h->leaves.size();
    report.links = h->links.size();
    report.memory_bytes = h->memory_bytes();
    report.seconds = clock.seconds();
    return std::make_unique<ClusteredTransport>(std::move(h), report);
}

}  // namespace rad
