// The transpose of the clustered gather is exact: for any u and v, u · (T v) = (Tᵀ u) · v, with T the
// leaves' unscaled gather (pull, links, push). The energy balancing of the leaves rests on it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "any_radiosity_balance.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"
#include "rad/transport/scene_transport.hpp"
#include "transport/clustered/cluster_balance.hpp"
#include "transport/clustered/cluster_flow.hpp"

namespace rad {
namespace {

class ClusterFlow : public ::testing::TestWithParam<bool> {};  // isotropic clusters or not

// The Cornell box clustered on base patches of 140 mm.
struct Cornell {
    explicit Cornell(bool isotropic)
        : scene(make_builtin_scene("cornell")), base(build_patches(scene, MeshingOptions{140.0})) {
        auto clustered =
            make_clustered_transport(scene, base, ClusteredOptions{.isotropic_clusters = isotropic});
        built.patches = &clustered->hierarchy().leaf_patches;
        built.transport = std::move(clustered);
    }
    Scene scene;
    PatchMesh base;
    SceneTransport built;
};

TEST_P(ClusterFlow, SpreadIsTheTransposeOfTheGather) {
    const Cornell cornell(GetParam());
    const SceneTransport& built = cornell.built;
    const auto& h = dynamic_cast<const ClusteredTransport&>(*built.transport).hierarchy();
    ASSERT_GT(h.links.size(), 1000u);
    const std::size_t n = h.leaves.size();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int trial = 0; trial < 3; ++trial) {
        std::vector<glm::dvec3> v(n);
        std::vector<double> u(n), spread_u(n);
        for (std::size_t k = 0; k < n; ++k) {
            v[k] = glm::dvec3(uniform(random));
            u[k] = uniform(random);
        }
        NodeValues b;
        Irradiance irradiance;
        pull(h, v, b);
        gather_push(h, b, irradiance);
        spread(h, u, spread_u);
        double forward = 0.0, backward = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            forward += u[k] * irradiance.element[h.leaves[k]].x;
            backward += spread_u[k] * v[k].x;
        }
        EXPECT_GT(forward, 0.0);
        EXPECT_NEAR(backward / forward, 1.0, 1e-9);
    }
}

// After balancing, what each leaf gathers of a uniform radiosity (its row sum) and the share of its own
// light that arrives somewhere (its column, per unit of exposed area) are the same: emitted = absorbed +
// escaped for any radiosity, not only a converged one.
TEST_P(ClusterFlow, BalancedLeavesSendWhatTheyGather) {
    const Cornell cornell(GetParam());
    const SceneTransport& built = cornell.built;
    const Transport& transport = *built.transport;
    const auto& h = dynamic_cast<const ClusteredTransport&>(transport).hierarchy();
    const std::size_t n = transport.size();
    const std::vector<double> rows = transport.reach();
    std::vector<double> weights(n), columns(n);
    for (std::size_t k = 0; k < n; ++k) weights[k] = transport.area[k] * h.receive_scale[k];
    spread(h, weights, columns);
    double worst = 0.0, lit = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double column = columns[k] * h.send_scale[k] / transport.area[k];
        worst = std::max(worst, std::abs(column - rows[k]));
        lit += rows[k] > 0.0 ? 1.0 : 0.0;
    }
    EXPECT_GT(lit, 0.9 * static_cast<double>(n));
    EXPECT_LT(worst, 1e-3);
    // Any radiosity, converged or not, balances.
    EXPECT_NEAR(test::any_radiosity_balance(transport, rows), 1.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Clusters, ClusterFlow, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return info.param ? "isotropic" : "oriented";
                         });

// Links that all but miss the leaves (here every factor divided by 10¹²) would ask for scales of 10¹², and
// a real model's slivers for more, up to overflow: the scales stop at kMaxLeafScale, and the gather stays
// finite.
TEST(ClusterBalance, ScalesStayBoundedWhereTheLinksMissTheLeaves) {
    const Cornell cornell(false);
    ClusterHierarchy h = dynamic_cast<const ClusteredTransport&>(*cornell.built.transport).hierarchy();
    for (ClusterLink& link : h.links) link.factor *= 1e-12f;
    balance_leaves(h);
    const auto largest = [](const std::vector<float>& scales) {
        float worst = 0.0f;
        for (const float s : scales) worst = std::isfinite(s) ? std::max(worst, s) : INFINITY;
        return worst;
    };
    EXPECT_LE(largest(h.receive_scale), kMaxLeafScale);
    EXPECT_LE(largest(h.send_scale), kMaxLeafScale);
    EXPECT_EQ(largest(h.receive_scale), static_cast<float>(kMaxLeafScale));  // the bound was needed
    std::vector<glm::dvec3> ones(h.leaves.size(), glm::dvec3(1.0)), gathered(h.leaves.size());
    FlowBuffers buffers;
    gather_leaves(h, ones, gathered, true, buffers);
    for (const glm::dvec3& g : gathered) ASSERT_TRUE(std::isfinite(g.x) && g.x >= 0.0);
}

}  // namespace
}  // namespace rad
