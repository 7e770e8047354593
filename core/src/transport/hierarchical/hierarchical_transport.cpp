// Gather along links and push-pull on a HierarchicalSystem, the leaves' form factors normalized, and the
// hierarchy as a Transport over its leaves.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "transport/hierarchical/hierarchical_corners.hpp"

namespace rad {

namespace {

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
    for (std::uint32_t c = 0; c < 4; ++c) {
        const std::uint32_t child = element.first_child + c;
        CornerIrradiance pushed = below[c];
        const double share = pushed_share(system, e, child);
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
    for (std::size_t k = 0; k < system.leaves.size(); ++k) {
        const std::uint32_t e = system.leaves[k];
        const double sent = system.send_scale.empty() ? 1.0 : static_cast<double>(system.send_scale[e]);
        b[e] = leaf_radiosity[k] * (exposed(system, e) * sent);
    }
    pull_to_inner_elements(system, b);
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
    const std::vector<glm::dvec3> ones(size(), glm::dvec3(1.0));
    std::vector<glm::dvec3> reached(size());
    gather(ones, reached);
    std::vector<double> reach(size());
    for (std::size_t k = 0; k < reach.size(); ++k) reach[k] = std::min(1.0, reached[k].x);
    return reach;
}

std::vector<double> HierarchicalTransport::escape() const {
    const HierarchicalSystem& h = *system_;
    // What does not reach a front (1 − reach) meets a back as often as the leaf's rays found; the rest
    // escapes. Taking the leaf's measured escape instead would split the difference between its reach and
    // its measure at random between the escape and the backs. Not measured: all of 1 − reach escapes.
    const std::vector<double> reached = reach();
    std::vector<double> out(h.leaves.size(), 1.0);
    for (std::size_t k = 0; k < out.size(); ++k) {
        const std::uint32_t e = h.leaves[k];
        if (e >= h.escaping_share.size() || e >= h.reaching_share.size() || h.escaping_share[e] < 0.0f ||
            h.reaching_share[e] < 0.0f)
            continue;
        const double escape = h.escaping_share[e];
        const double exposed_share = exposed(h, e);
        if (!(escape > 0.0) || !(exposed_share > 0.0)) {
            out[k] = 0.0;
            continue;
        }
        const double front = std::min(1.0, static_cast<double>(h.reaching_share[e]) / exposed_share);
        const double back = std::max(0.0, 1.0 - front - escape);
        const double lost = std::max(0.0, 1.0 - reached[k]);
        out[k] = std::clamp(lost - back, 0.0, lost);
    }
    return out;
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
