// The clustered transport's aimed direct light and its shadow-edge splitting, on a shadow edge with a closed
// form (assets/hard/shadow_edge.obj): a floor lit by a square light, half of it shaded by a plate; the light
// and the plate reflect nothing, so every floor leaf's radiosity is its direct light alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rad/geometry/point_polygon_factor.hpp"
#include "rad/scene/scene_loader.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

const std::string kShadowEdge = std::string(RAD_SOURCE_DIR) + "/assets/hard/shadow_edge.obj";

// B = ρ E F at floor point p (ρ = 0.5, E = π), F the factor of the part of the light the plate leaves
// visible.
double exact_radiosity(const glm::dvec3& p) {
    const double x0 = std::max(-0.1, 0.06 - p.x);
    if (x0 >= 0.1) return 0.0;
    const glm::dvec3 light[4] = {{x0, 0.5, -0.1}, {0.1, 0.5, -0.1}, {0.1, 0.5, 0.1}, {x0, 0.5, 0.1}};
    return 0.5 * std::numbers::pi * point_polygon_factor(p, {0.0, 1.0, 0.0}, light);
}

// B at a point of the floor's leaf, relative to the lit floor's value, sampled on a 4 × 4 grid of its
// bounding square (the floor's leaves are squares): the leaf's exact mean.
double exact_leaf_mean(const PatchMesh& leaves, std::size_t k) {
    const Patch& patch = leaves.patches[k];
    const double half = 0.5 * std::sqrt(patch.area);
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            sum += exact_radiosity(patch.centroid + glm::dvec3(half * ((i + 0.5) / 2.0 - 1.0), 0.0,
                                                               half * ((j + 0.5) / 2.0 - 1.0)));
    return sum / 16.0;
}

TEST(ClusteredDirectLight, FloorLeavesTakeTheClosedFormAcrossAShadowEdge) {
    const auto solved = test::solve_scene(load_scene(kShadowEdge), Subdivision::clustered);
    const PatchMesh& leaves = *solved->system.patches;
    const Transport& transport = *solved->system.transport;
    const double lit = exact_radiosity({0.3, 0.0, 0.0});
    double error = 0.0, area = 0.0, smallest_penumbra_leaf = 1.0;
    std::size_t floor_leaves = 0;
    for (std::size_t k = 0; k < leaves.size(); ++k) {
        const Patch& patch = leaves.patches[k];
        if (transport.reflectance[k].x != 0.5 || patch.normal.y < 0.99) continue;  // the floor
        ++floor_leaves;
        const double a = transport.area[k];
        error += a * std::abs(solved->radiosity[k].x - exact_leaf_mean(leaves, k)) / lit;
        area += a;
        if (std::abs(patch.centroid.x - 0.06) < 0.1 && std::abs(patch.centroid.z) < 0.3)
            smallest_penumbra_leaf = std::min(smallest_penumbra_leaf, std::sqrt(patch.area));
    }
    error /= area;
    std::printf(
        "[ figures  ] shadow edge, clustered: %zu floor leaves, mean error %.4f of the lit value, "
        "smallest leaf in the penumbra %.4f\n",
        floor_leaves, error, smallest_penumbra_leaf);
    // The penumbra (0.2 wide) is split below the base patches' 0.25 and the links' own sizes.
    EXPECT_LT(smallest_penumbra_leaf, 0.05);
    EXPECT_LT(error, 0.02);
    const EnergyBalance balance = energy_balance(transport, solved->radiosity);
    EXPECT_NEAR(balance.absorbed.x + balance.escaped.x, balance.emitted.x, 5e-3 * balance.emitted.x);
}

}  // namespace
}  // namespace rad
