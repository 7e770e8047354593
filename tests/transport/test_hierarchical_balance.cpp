// The leaves of hierarchical radiosity balanced (balance_leaf_form_factors): spread_leaves is the exact
// transpose of the leaves' gather, and after balancing each leaf sends what it gathers, so emitted = absorbed
// + escaped for any radiosity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "any_radiosity_balance.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "rad/transport/scene_transport.hpp"

namespace rad {
namespace {

// The Cornell box, hierarchical on base patches of 140 mm (open at the front: light escapes).
struct Cornell {
    Cornell() : scene(make_builtin_scene("cornell")), base(build_patches(scene, MeshingOptions{140.0})) {
        TransportSettings settings;
        settings.subdivision = Subdivision::hierarchical;
        built = build_scene_transport(scene, base, settings);
    }
    const HierarchicalSystem& system() const {
        return dynamic_cast<const HierarchicalTransport&>(*built.transport).system();
    }
    Scene scene;
    PatchMesh base;
    SceneTransport built;
};

// Per element of the tree, the leaves' values (leaf k is element system.leaves[k]); 0 elsewhere.
std::vector<double> per_element(const HierarchicalSystem& system, const std::vector<double>& per_leaf) {
    std::vector<double> out(system.tree.size(), 0.0);
    for (std::size_t k = 0; k < per_leaf.size(); ++k) out[system.leaves[k]] = per_leaf[k];
    return out;
}

// u · (exposed ∘ gather(B)) = spread(u) · (send ∘ B): the gather per unit of exposed area, the spread per
// leaf of the light its exposed part sends before send_scale.
TEST(HierarchicalBalance, SpreadIsTheTransposeOfTheGather) {
    const Cornell cornell;
    const Transport& transport = *cornell.built.transport;
    const HierarchicalSystem& h = cornell.system();
    ASSERT_GT(h.links.size(), 1000u);
    ASSERT_GT(h.leaves.size(), cornell.base.size());  // refined
    const std::size_t n = transport.size();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int trial = 0; trial < 3; ++trial) {
        std::vector<glm::dvec3> b(n), gathered(n);
        std::vector<double> u(n);
        for (std::size_t k = 0; k < n; ++k) {
            b[k] = glm::dvec3(uniform(random));
            u[k] = uniform(random);
        }
        transport.gather(b, gathered);
        std::vector<double> spread(h.tree.size());
        spread_leaves(h, per_element(h, u), spread);
        double forward = 0.0, backward = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint32_t e = h.leaves[k];
            forward += u[k] * static_cast<double>(h.exposed_share[e]) * gathered[k].x;
            backward += spread[e] * static_cast<double>(h.send_scale[e]) * b[k].x;
        }
        EXPECT_GT(forward, 0.0);
        EXPECT_NEAR(backward / forward, 1.0, 1e-9);
    }
}

// What each leaf gathers of a uniform radiosity (its row, reach()) and the share of its own light that
// arrives somewhere (its column, per unit of exposed area) are the same after balancing. Before, the links
// were scaled by rows only, and the box lost 5 % of its light (docs/measurements.md).
TEST(HierarchicalBalance, BalancedLeavesSendWhatTheyGather) {
    const Cornell cornell;
    const Transport& transport = *cornell.built.transport;
    const HierarchicalSystem& h = cornell.system();
    const std::size_t n = transport.size();
    const std::vector<double> rows = transport.reach();
    std::vector<double> whole_area(n);
    for (std::size_t k = 0; k < n; ++k) whole_area[k] = h.tree[h.leaves[k]].shape.area;
    std::vector<double> spread(h.tree.size());
    spread_leaves(h, per_element(h, whole_area), spread);
    double worst = 0.0, lit = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t e = h.leaves[k];
        const double column = spread[e] * static_cast<double>(h.send_scale[e]) / transport.area[k];
        worst = std::max(worst, std::abs(column - rows[k]));
        lit += rows[k] > 0.0 ? 1.0 : 0.0;
    }
    EXPECT_GT(lit, 0.9 * static_cast<double>(n));
    EXPECT_LT(worst, 1e-3);
    // Any radiosity, converged or not, balances.
    EXPECT_NEAR(test::any_radiosity_balance(transport, rows), 1.0, 1e-3);
}

}  // namespace
}  // namespace rad
