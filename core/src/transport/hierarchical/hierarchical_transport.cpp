// Gather along links and push-pull on a HierarchicalSystem, the leaves' form factors normalized, and the
// hierarchy as a Transport over its leaves.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"

namespace rad {

namespace {

double exposed(const HierarchicalSystem& system, std::uint32_t e) {
    return std::max(0.0, static_cast<double>(system.exposed_share[e]));
}

// Irradiance at an element's corners (a triangle uses three).
using CornerIrradiance = std::array<glm::dvec3, 4>;

// Irradiance gathered by each element along its own links, at its corners.
// `gathered` is all zero on entry and holds one entry per element; only receivers' entries are written.
void gather_links(const HierarchicalSystem& system, std::span<const glm::dvec3> radiosity,
                  std::span<CornerIrradiance> gathered) {
    const std::size_t runs = system.receiver_runs.empty() ? 0 : system.receiver_runs.size() - 1;
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, runs, 256), [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t k = range.begin(); k < range.end(); ++k) {
                CornerIrradiance sum{};
                const std::uint32_t first = system.receiver_runs[k], last = system.receiver_runs[k + 1];
                for (std::uint32_t l = first; l < last; ++l) {
                    const HierarchicalLink& link = system.links[l];
                    const glm::dvec3& b = radiosity[link.source];
                    for (int c = 0; c < 4; ++c) sum[c] += static_cast<double>(link.factor[c]) * b;
                }
                gathered[system.links[first].receiver] = sum;
            }
        });
}

// Zeroes what gather_links wrote: O(receivers), where clearing the whole buffer each step would be
// O(elements) and allocating it anew a million-element page-fault storm per step.
void clear_gathered(const HierarchicalSystem& system, std::span<CornerIrradiance> gathered) {
    for (std::size_t k = 0; k + 1 < system.receiver_runs.size(); ++k)
        gathered[system.links[system.receiver_runs[k]].receiver] = CornerIrradiance{};
}

// The irradiance at the children's corners, interpolated from the parent's (ElementTree::split's layout).
std::array<CornerIrradiance, 4> child_corners(const CornerIrradiance& h, bool triangle) {
    const glm::dvec3 m01 = 0.5 * (h[0] + h[1]), m12 = 0.5 * (h[1] + h[2]);
    if (triangle) {
        const glm::dvec3 m20 = 0.5 * (h[2] + h[0]);
        return {{{h[0], m01, m20, m20}, {m01, h[1], m12, m12}, {m20, m12, h[2], h[2]}, {m01, m12, m20, m20}}};
    }
    const glm::dvec3 m23 = 0.5 * (h[2] + h[3]), m30 = 0.5 * (h[3] + h[0]);
    const glm::dvec3 centre = 0.25 * (h[0] + h[1] + h[2] + h[3]);
    return {{{h[0], m01, centre, m30},
             {m01, h[1], m12, centre},
             {centre, m12, h[2], m23},
             {m30, centre, m23, h[3]}}};
}

// Pushes the irradiance gathered above down to the leaves, where B = E + ρ × the irradiance's mean over the
// leaf, and pulls the area-weighted mean of the children back up into every inner element.
void push_pull(const HierarchicalSystem& system, std::uint32_t e, const CornerIrradiance& above,
               std::span<const CornerIrradiance> gathered, std::span<glm::dvec3> out,
               std::span<glm::dvec3> irradiance_out) {
    const Element& element = system.tree[e];
    CornerIrradiance irradiance;
    for (int c = 0; c < 4; ++c) irradiance[c] = above[c] + gathered[e][c];
    if (element.is_leaf()) {
        const double scale = system.leaf_scale.empty() ? 1.0 : static_cast<double>(system.leaf_scale[e]);
        const glm::dvec3 mean =
            scale * (element.is_triangle()
                         ? (irradiance[0] + irradiance[1] + irradiance[2]) / 3.0
                         : 0.25 * (irradiance[0] + irradiance[1] + irradiance[2] + irradiance[3]));
        if (!irradiance_out.empty()) irradiance_out[e] = mean;
        // Only the exposed part emits; B here is the mean over the whole leaf.
        out[e] = system.emission[e] * exposed(system, e) + system.reflectance[e] * mean;
        return;
    }
    const std::array<CornerIrradiance, 4> below = child_corners(irradiance, element.is_triangle());
    glm::dvec3 sum(0.0);
    double area = 0.0;
    const double parent_exposed = exposed(system, e);
    for (std::uint32_t c = 0; c < 4; ++c) {
        const std::uint32_t child = element.first_child + c;
        // The irradiance above is a mean over the whole parent, its covered part's zeros included; a child
        // gets the exposed part's irradiance times its own exposed share.
        CornerIrradiance pushed = below[c];
        const double share = parent_exposed > 0.0
                                 ? std::min(1.0 / parent_exposed, exposed(system, child) / parent_exposed)
                                 : 0.0;
        for (glm::dvec3& h : pushed) h *= share;
        push_pull(system, child, pushed, gathered, out, irradiance_out);
        sum += system.tree[child].shape.area * out[child];
        area += system.tree[child].shape.area;
    }
    out[e] = area > 0.0 ? sum / area : glm::dvec3(0.0);
}

// Per element, the mean radiosity over the whole element from the leaves' (of their exposed parts):
// leaves scaled by their exposed share, inner elements the area-weighted mean of their children (children
// come after their parents in the tree).
void element_radiosity(const HierarchicalSystem& system, std::span<const glm::dvec3> leaf_radiosity,
                       std::vector<glm::dvec3>& b) {
    b.assign(system.tree.size(), glm::dvec3(0.0));
    for (std::size_t k = 0; k < system.leaves.size(); ++k)
        b[system.leaves[k]] = leaf_radiosity[k] * exposed(system, system.leaves[k]);
    for (std::size_t e = b.size(); e-- > 0;) {
        const Element& element = system.tree[e];
        if (element.is_leaf()) continue;
        glm::dvec3 sum(0.0);
        double area = 0.0;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c) {
            sum += system.tree[c].shape.area * b[c];
            area += system.tree[c].shape.area;
        }
        b[e] = sum / area;
    }
}

// Per unit of a leaf's exposed area, from the mean over the whole leaf.
double per_exposed_area(const HierarchicalSystem& system, std::uint32_t leaf) {
    return 1.0 / std::max(1e-6, exposed(system, leaf));
}

}  // namespace

void gather_push_pull(const HierarchicalSystem& system, std::span<const glm::dvec3> radiosity,
                      std::span<glm::dvec3> out, std::span<glm::dvec3> leaf_irradiance) {
    // Kept between steps on this thread (a solver steps on one thread), all zero between calls. The
    // lambdas below run on other threads, so they must see it through `gathered`, not by its name.
    thread_local std::vector<CornerIrradiance> buffer;
    if (buffer.size() < system.tree.size()) buffer.resize(system.tree.size(), CornerIrradiance{});
    const std::span<CornerIrradiance> gathered(buffer);
    gather_links(system, radiosity, gathered);
    const auto bases = static_cast<std::uint32_t>(system.tree.base_size());
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, bases, 16),
                      [&](const tbb::blocked_range<std::uint32_t>& range) {
                          for (std::uint32_t b = range.begin(); b < range.end(); ++b)
                              push_pull(system, b, CornerIrradiance{}, gathered, out, leaf_irradiance);
                      });
    clear_gathered(system, gathered);
}

void normalize_leaf_form_factors(HierarchicalSystem& system, std::span<const float> reaching) {
    const std::size_t n = system.tree.size();
    system.leaf_scale.clear();
    // What each leaf gathers when every exposed part shines with radiosity 1: its links' form-factor sum
    // over the scene, times its exposed_share.
    std::vector<glm::dvec3> exposed_one(n), out(n), gathered(n, glm::dvec3(0.0));
    for (std::size_t e = 0; e < n; ++e)
        exposed_one[e] = glm::dvec3(exposed(system, static_cast<std::uint32_t>(e)));
    gather_push_pull(system, exposed_one, out, gathered);
    system.leaf_scale.assign(n, 1.0f);
    for (std::uint32_t e = 0; e < n; ++e) {
        if (!system.tree[e].is_leaf() || !(gathered[e].x > 0.0) || !(reaching[e] >= 0.0f)) continue;
        // The measurement is a share of kReachingRays rays: move towards it only by what exceeds twice its
        // standard error, so an open scene's leaves (where some rays leave) do not take on its noise, while
        // in a closed room (no ray leaves, no noise) every leaf sums to exactly 1.
        const double exposed_share = std::max(1e-6, exposed(system, e));
        const double measured = reaching[e], links = gathered[e].x;
        const double share = std::min(1.0, measured / exposed_share);  // of the rays from exposed points
        const double noise = exposed_share * std::sqrt(share * (1.0 - share) / kReachingRays);
        const double excess = std::max(0.0, std::abs(measured - links) - 2.0 * noise);
        const double target = links + std::copysign(excess, measured - links);
        system.leaf_scale[e] = static_cast<float>(std::clamp(target / links, 0.0, 4.0));
    }
}

HierarchicalTransport::HierarchicalTransport(std::unique_ptr<HierarchicalSystem> system,
                                             const HierarchicalReport& report)
    : system_(std::move(system)), report_(report) {
    const HierarchicalSystem& h = *system_;
    const std::size_t n = h.leaves.size();
    area.resize(n);
    reflectance.resize(n);
    emission.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t e = h.leaves[k];
        area[k] = h.tree[e].shape.area / per_exposed_area(h, e);
        reflectance[k] = h.reflectance[e];
        emission[k] = h.emission[e];
    }
}

void HierarchicalTransport::gather(std::span<const glm::dvec3> radiosity,
                                   std::span<glm::dvec3> irradiance) const {
    const HierarchicalSystem& h = *system_;
    // Kept between calls on this thread, as gather_push_pull's own buffer is.
    thread_local std::vector<glm::dvec3> element, out, leaf_irradiance;
    element_radiosity(h, radiosity, element);
    out.resize(h.tree.size());
    leaf_irradiance.resize(h.tree.size());
    gather_push_pull(h, element, out, leaf_irradiance);
    for (std::size_t k = 0; k < h.leaves.size(); ++k)
        irradiance[k] = leaf_irradiance[h.leaves[k]] * per_exposed_area(h, h.leaves[k]);
}

std::vector<double> HierarchicalTransport::reach() const {
    const HierarchicalSystem& h = *system_;
    const std::size_t n = h.tree.size();
    std::vector<glm::dvec3> ones(n, glm::dvec3(1.0)), out(n), reached(n, glm::dvec3(0.0));
    gather_push_pull(h, ones, out, reached);
    std::vector<double> reach(h.leaves.size());
    for (std::size_t k = 0; k < reach.size(); ++k)
        reach[k] = std::min(1.0, reached[h.leaves[k]].x * per_exposed_area(h, h.leaves[k]));
    return reach;
}

std::vector<double> HierarchicalTransport::escape() const {
    const HierarchicalSystem& h = *system_;
    std::vector<double> share(h.leaves.size(), 1.0);  // not measured: all of 1 − reach
    for (std::size_t k = 0; k < share.size(); ++k) {
        const std::uint32_t e = h.leaves[k];
        if (e < h.escaping_share.size() && h.escaping_share[e] >= 0.0f) share[k] = h.escaping_share[e];
    }
    return share;
}

TransportReport HierarchicalTransport::report() const {
    TransportReport r;
    r.kind = "hierarchical";
    r.interaction_name = "links";
    r.elements = size();
    r.interactions = report_.links;
    r.memory_bytes = report_.memory_bytes;
    r.rays = report_.rays;
    r.seconds = report_.refine_seconds + report_.solve_seconds;
    r.form_factor_passes = 1;
    r.details = {{"base_patches", static_cast<double>(report_.base_patches)},
                 {"first_links", static_cast<double>(report_.first_links)},
                 {"tree_elements", static_cast<double>(report_.elements)},
                 {"leaves", static_cast<double>(report_.leaves)},
                 {"rounds", static_cast<double>(report_.rounds)},
                 {"refine_seconds", report_.refine_seconds},
                 {"round_solve_seconds", report_.solve_seconds},
                 {"min_patch_size", report_.min_patch_size}};
    if (report_.limited) r.notes = "refinement stopped at the element, link or memory limit";
    return r;
}

std::unique_ptr<HierarchicalTransport> make_hierarchical_transport(const Scene& scene, const PatchMesh& base,
                                                                   const HierarchicalOptions& options,
                                                                   Progress* progress) {
    HierarchicalReport report;
    std::unique_ptr<HierarchicalSystem> system =
        build_hierarchical_system(scene, base, options, &report, progress);
    return std::make_unique<HierarchicalTransport>(std::move(system), report);
}

}  // namespace rad
