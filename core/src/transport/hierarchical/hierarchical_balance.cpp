// The leaves' form factors of hierarchical radiosity scaled to the measured reach (rows), and balanced so
// that each leaf sends what it gathers (columns too), with the push-pull's transpose that needs.
#include <algorithm>
#include <array>
#include <cmath>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "transport/hierarchical/hierarchical_corners.hpp"
#include "transport/leaf_balance.hpp"

namespace rad {

namespace {

// Per element: the leaves' values times their exposed share, the inner elements' pulled up.
std::vector<glm::dvec3> pull_elements(const HierarchicalSystem& system, std::span<const double> leaf_value) {
    std::vector<glm::dvec3> b(system.tree.size(), glm::dvec3(0.0));
    for (std::uint32_t e = 0; e < b.size(); ++e)
        if (system.tree[e].is_leaf()) b[e] = glm::dvec3(leaf_value[e] * exposed(system, e));
    pull_to_inner_elements(system, b);
    return b;
}

// Per leaf, the mean irradiance over the whole leaf when the leaves' exposed parts shine with leaf_value
// (the scales as they stand in `system`).
std::vector<double> gather_leaves(const HierarchicalSystem& system, std::span<const double> leaf_value) {
    const std::vector<glm::dvec3> b = pull_elements(system, leaf_value);
    std::vector<glm::dvec3> out(b.size()), irradiance(b.size(), glm::dvec3(0.0));
    gather_push_pull(system, b, out, irradiance);
    std::vector<double> result(b.size());
    for (std::size_t e = 0; e < b.size(); ++e) result[e] = irradiance[e].x;
    return result;
}

// coefficient[t][i][c'][c]: how much of a parent's corner c child i's corner c' takes (t = 1: a triangle),
// child_corners applied to each corner alone.
using ChildCoefficients = std::array<std::array<std::array<std::array<double, 4>, 4>, 4>, 2>;

ChildCoefficients child_coefficients() {
    ChildCoefficients k{};
    for (int t = 0; t < 2; ++t)
        for (int c = 0; c < 4; ++c) {
            CornerIrradiance unit{};
            unit[c] = glm::dvec3(1.0);
            const std::array<CornerIrradiance, 4> below = child_corners(unit, t == 1);
            for (int i = 0; i < 4; ++i)
                for (int cc = 0; cc < 4; ++cc) k[t][i][cc][c] = below[i][cc].x;
        }
    return k;
}

// Push, transposed: per element, the weight its corners' irradiance carries to the leaves' means.
std::vector<std::array<double, 4>> corner_weights(const HierarchicalSystem& system,
                                                  std::span<const double> weights) {
    static const ChildCoefficients coefficient = child_coefficients();
    const std::size_t n = system.tree.size();
    std::vector<std::array<double, 4>> corner(n, std::array<double, 4>{});
    for (std::size_t e = n; e-- > 0;) {
        const Element& element = system.tree[e];
        const int t = element.is_triangle() ? 1 : 0;
        if (element.is_leaf()) {
            const double scale = system.leaf_scale.empty() ? 1.0 : static_cast<double>(system.leaf_scale[e]);
            const int corners = t == 1 ? 3 : 4;
            for (int c = 0; c < corners; ++c) corner[e][c] = scale * weights[e] / corners;
            continue;
        }
        for (int i = 0; i < 4; ++i) {
            const std::uint32_t child = element.first_child + static_cast<std::uint32_t>(i);
            const double share = pushed_share(system, static_cast<std::uint32_t>(e), child);
            for (int c = 0; c < 4; ++c)
                for (int cc = 0; cc < 4; ++cc)
                    corner[e][c] += share * coefficient[t][i][cc][c] * corner[child][cc];
        }
    }
    return corner;
}

// Leaves pooled until their rays measure the links' bias to a few per cent.
constexpr double kPoolLeaves = 16.0;

// Per element (leaves), the ratio of measured reach to the links' row sum over a pool of leaves around it:
// its base patch's leaves when they are kPoolLeaves, else its surface's. The links' error varies slowly over
// a surface; one leaf's 64 rays are too noisy to correct it alone.
std::vector<double> pooled_bias(const HierarchicalSystem& system, std::span<const float> reaching,
                                std::span<const double> links) {
    struct Pool {
        double measured = 0.0, linked = 0.0, leaves = 0.0;
        double ratio() const { return linked > 0.0 ? measured / linked : 1.0; }
    };
    std::vector<Pool> patch(system.tree.base_size());
    std::vector<Pool> surface;
    const auto surface_of = [&](std::uint32_t e) {
        return system.tree[system.tree[e].base_patch].shape.surface;
    };
    for (std::uint32_t e = 0; e < system.tree.size(); ++e) {
        if (!system.tree[e].is_leaf() || !(reaching[e] >= 0.0f) || !(links[e] > 0.0)) continue;
        const double area = system.tree[e].shape.area;
        Pool& pool = patch[system.tree[e].base_patch];
        pool.measured += area * reaching[e];
        pool.linked += area * links[e];
        pool.leaves += 1.0;
        const std::uint32_t s = surface_of(e);
        if (surface.size() <= s) surface.resize(s + 1);
        surface[s].measured += area * reaching[e];
        surface[s].linked += area * links[e];
        surface[s].leaves += 1.0;
    }
    std::vector<double> bias(system.tree.size(), 1.0);
    for (std::uint32_t e = 0; e < system.tree.size(); ++e) {
        if (!system.tree[e].is_leaf() || !(links[e] > 0.0)) continue;
        const Pool& own = patch[system.tree[e].base_patch];
        const std::uint32_t s = surface_of(e);
        bias[e] = own.leaves >= kPoolLeaves || s >= surface.size() ? own.ratio() : surface[s].ratio();
    }
    return bias;
}

// Per leaf, the row sum it is scaled to: the links' own corrected by their pooled bias, then moved towards
// the leaf's own measurement by what exceeds twice its standard error.
std::vector<double> leaf_reach_targets(const HierarchicalSystem& system, std::span<const float> reaching,
                                       std::span<const double> links) {
    const std::vector<double> bias = pooled_bias(system, reaching, links);
    std::vector<double> target(system.tree.size(), 0.0);
    for (std::uint32_t e = 0; e < system.tree.size(); ++e) {
        if (!system.tree[e].is_leaf() || !(links[e] > 0.0)) continue;
        if (!(reaching[e] >= 0.0f)) {
            target[e] = links[e];  // not measured: the links as they are
            continue;
        }
        // An open scene's leaves (where some rays leave) do not take on the measurement's noise, while in a
        // closed room (no ray leaves, no noise) every leaf sums to exactly 1.
        const double exposed_share = std::max(1e-6, exposed(system, e));
        const double measured = reaching[e];
        const double prior = std::min(exposed_share, links[e] * bias[e]);
        const double share = std::min(1.0, measured / exposed_share);  // of the rays from exposed points
        const double noise = exposed_share * std::sqrt(share * (1.0 - share) / kReachingRays);
        const double excess = std::max(0.0, std::abs(measured - prior) - 2.0 * noise);
        target[e] = prior + std::copysign(excess, measured - prior);
    }
    return target;
}

}  // namespace

void spread_leaves(const HierarchicalSystem& system, std::span<const double> weights, std::span<double> out) {
    const std::vector<std::array<double, 4>> corner = corner_weights(system, weights);
    // The links, transposed: each source collects what its receivers' corners take of it.
    const std::size_t n = system.tree.size();
    std::vector<double> sent(n, 0.0);
    for (const HierarchicalLink& link : system.links)
        for (int c = 0; c < 4; ++c)
            sent[link.source] += static_cast<double>(link.factor[c]) * corner[link.receiver][c];
    // Pull, transposed: an element's share goes down to its children by their areas.
    for (std::size_t e = 0; e < n; ++e) {
        const Element& element = system.tree[e];
        if (element.is_leaf()) {
            out[e] = sent[e] * exposed(system, static_cast<std::uint32_t>(e));
            continue;
        }
        double area = 0.0;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            area += system.tree[c].shape.area;
        if (!(area > 0.0)) continue;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c)
            sent[c] += sent[e] * system.tree[c].shape.area / area;
    }
}

void normalize_leaf_form_factors(HierarchicalSystem& system, std::span<const float> reaching) {
    system.leaf_scale.clear();
    system.send_scale.clear();
    const std::vector<double> links = gather_leaves(system, std::vector<double>(system.tree.size(), 1.0));
    const std::vector<double> target = leaf_reach_targets(system, reaching, links);
    system.leaf_scale.assign(system.tree.size(), 1.0f);
    for (std::size_t e = 0; e < target.size(); ++e)
        if (links[e] > 0.0)
            system.leaf_scale[e] = static_cast<float>(std::clamp(target[e] / links[e], 0.0, 4.0));
}

double balance_leaf_form_factors(HierarchicalSystem& system, std::span<const float> reaching) {
    const std::size_t n = system.tree.size();
    system.leaf_scale.clear();
    system.send_scale.clear();
    const std::vector<double> links = gather_leaves(system, std::vector<double>(n, 1.0));
    const std::vector<double> target = leaf_reach_targets(system, reaching, links);
    std::vector<double> area(n);
    for (std::size_t e = 0; e < n; ++e) area[e] = system.tree[e].shape.area;
    // Inner elements have target 0, so scales 0, which neither the push nor the pull reads.
    const LeafScales scales = balance_rows_and_columns(
        target, area,
        [&](std::span<const double> send, std::vector<double>& rows) { rows = gather_leaves(system, send); },
        [&](std::span<const double> weights, std::span<double> columns) {
            spread_leaves(system, weights, columns);
        });
    system.leaf_scale.assign(scales.receive.begin(), scales.receive.end());
    system.send_scale.assign(scales.send.begin(), scales.send.end());
    return scales.error;
}

}  // namespace rad
