// A solution drawn on patches of the display's own (make_display_patches, trace_display_patch_gather): each
// display patch takes the leaves under it, by area and exposed share; its own gather shows a furnace's exact
// radiosity, and while the bounces are stepped it shows the bounces of its step.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <numeric>

#include "display/display_patch_gather.hpp"
#include "display/display_patches.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

PatchMesh mesh_of(const Scene& scene, double size) {
    return build_patches(scene, MeshingOptions{.patch_size = size});
}

DisplayPatches display_over(const Scene& scene, const PatchMesh& solution, std::span<const double> exposed,
                            double size) {
    const RayScene rays(solution);
    return make_display_patches(scene, solution, rays, exposed, size);
}

double share_sum(const PatchRestriction& r, std::size_t d) {
    return std::accumulate(r.share.begin() + r.begin[d], r.share.begin() + r.begin[d + 1], 0.0);
}

TEST(DisplayPatches, NestedLeavesShareEachDisplayPatchEqually) {
    // builtin:perpendicular's two unit squares: leaves of 1/8 under display patches of 1/4, four to each.
    const Scene scene = make_perpendicular_squares();
    const PatchMesh solution = mesh_of(scene, 0.125);
    const std::vector<double> exposed(solution.size(), 1.0);
    const DisplayPatches d = display_over(scene, solution, exposed, 0.25);
    ASSERT_EQ(d.mesh.size(), 32u);
    const PatchRestriction& r = d.from_solution;
    ASSERT_EQ(r.size(), d.mesh.size());
    EXPECT_EQ(r.source_count, solution.size());
    for (std::size_t p = 0; p < r.size(); ++p) {
        ASSERT_EQ(r.begin[p + 1] - r.begin[p], 4u) << "display patch " << p;
        for (std::uint32_t k = r.begin[p]; k < r.begin[p + 1]; ++k) {
            EXPECT_FLOAT_EQ(r.share[k], 0.25f);
            const Patch& leaf = solution.patches[r.source[k]];
            EXPECT_EQ(leaf.surface, d.mesh.patches[p].surface);
            EXPECT_LT(glm::length(leaf.centroid - d.mesh.patches[p].centroid), 0.1);
        }
        EXPECT_DOUBLE_EQ(d.exposed[p], 1.0);
    }
}

TEST(DisplayPatches, RestrictingALinearFieldGivesItsValueAtEachPatchCentre) {
    // Leaves of 1/7 under display patches of 1/4 (not nested): the samples' leaves average a linear field
    // to its value at the display patch's centre, within a small share of the field's step across a leaf
    // (0.36 to 0.51 here; the worst patch is 0.08 off): a sample given a neighbour's leaf would be off by
    // that step.
    const Scene scene = make_perpendicular_squares();
    const PatchMesh solution = mesh_of(scene, 0.15);
    const auto field = [](const glm::dvec3& p) { return 1.0 + 2.0 * p.x + 3.0 * p.y + 1.5 * p.z; };
    std::vector<glm::dvec3> values;
    for (const Patch& leaf : solution.patches) values.emplace_back(field(leaf.centroid));
    const std::vector<double> exposed(solution.size(), 1.0);
    const DisplayPatches d = display_over(scene, solution, exposed, 0.25);
    const std::vector<glm::dvec3> restricted = d.from_solution.apply(values);
    ASSERT_EQ(restricted.size(), d.mesh.size());
    for (std::size_t p = 0; p < d.mesh.size(); ++p) {
        EXPECT_NEAR(restricted[p].x, field(d.mesh.patches[p].centroid), 0.12) << "display patch " << p;
        EXPECT_NEAR(share_sum(d.from_solution, p), 1.0, 1e-6);
    }
}

TEST(DisplayPatches, CoveredLeavesTakeNoShareOfAPatchThatIsPartlyExposed) {
    // Leaves of 1/10; those whose centres lie at x < 0.35 are covered (as under a block). The display patch
    // over x in [0.25, 0.5] has one column of its 4 x 4 samples on a covered leaf: exposed 3/4, and the
    // covered leaf takes no share. The patches over x < 0.25, all covered, keep their leaves by count.
    const Scene scene = make_perpendicular_squares();
    const PatchMesh solution = mesh_of(scene, 0.1);
    std::vector<double> exposed(solution.size());
    for (std::size_t q = 0; q < solution.size(); ++q)
        exposed[q] = solution.patches[q].centroid.x < 0.35 ? 0.0 : 1.0;
    const DisplayPatches d = display_over(scene, solution, exposed, 0.25);
    int partly = 0, covered = 0;
    for (std::size_t p = 0; p < d.mesh.size(); ++p) {
        const double x = d.mesh.patches[p].centroid.x;
        EXPECT_NEAR(share_sum(d.from_solution, p), 1.0, 1e-6);
        if (std::abs(x - 0.375) < 1e-9) {
            ++partly;
            EXPECT_DOUBLE_EQ(d.exposed[p], 0.75);
            for (std::uint32_t k = d.from_solution.begin[p]; k < d.from_solution.begin[p + 1]; ++k) {
                if (exposed[d.from_solution.source[k]] == 0.0) {
                    EXPECT_EQ(d.from_solution.share[k], 0.0f);
                }
            }
        } else if (x < 0.25) {
            ++covered;
            EXPECT_DOUBLE_EQ(d.exposed[p], 0.0);
        }
    }
    EXPECT_GT(partly, 0);
    EXPECT_GT(covered, 0);
}

TEST(DisplayPatches, ExposedSharesOfAnotherCountAreRefused) {
    const Scene scene = make_perpendicular_squares();
    const PatchMesh solution = mesh_of(scene, 0.25);
    const std::vector<double> exposed(solution.size() - 1, 1.0);
    EXPECT_THROW(display_over(scene, solution, exposed, 0.25), std::invalid_argument);
    const DisplayPatches d = display_over(scene, solution, std::vector<double>(solution.size(), 1.0), 0.25);
    EXPECT_THROW(d.from_solution.apply(std::vector<glm::dvec3>(2)), std::invalid_argument);
}

// A clustered furnace (every face ρ = 0.5, E = 1, so B = 2) drawn on display patches with their own gather.
struct GatheredFurnace {
    std::unique_ptr<test::SolvedScene> solved;
    DisplayMesh display;
};

GatheredFurnace gathered_furnace(std::size_t budget = kPatchGatherRayBudget) {
    GatheredFurnace g{test::solve_scene(make_furnace(1000), Subdivision::clustered), {}};
    const PatchMesh& leaves = *g.solved->system.patches;
    const Transport& t = *g.solved->system.transport;
    const RayScene rays(leaves);
    DisplayPatches own =
        make_display_patches(g.solved->scene, leaves, rays, std::vector<double>(leaves.size(), 1.0),
                             default_patch_size(g.solved->scene));
    const std::vector<glm::dvec3> emission = own.from_solution.apply(t.emission);
    const std::vector<glm::dvec3> reflectance = own.from_solution.apply(t.reflectance);
    g.display = build_display_mesh(own.mesh);
    g.display.from_solution = std::move(own.from_solution);
    trace_display_patch_gather(g.display, {.patches = &own.mesh,
                                           .exposed = own.exposed,
                                           .solution = &leaves,
                                           .solution_rays = &rays,
                                           .ray_budget = budget});
    light_display_patch_gather(g.display,
                               {.emission = emission,
                                .reflectance = reflectance,
                                .source = std::vector<glm::dvec3>(leaves.size(), glm::dvec3(0.0))});
    return g;
}

// The largest relative difference of any vertex's radiance from B / π.
double worst_error(const std::vector<glm::vec3>& shown, double b) {
    double worst = 0.0;
    for (const glm::vec3& l : shown)
        worst = std::max(worst, std::abs(static_cast<double>(l.y) * std::numbers::pi - b) / b);
    return worst;
}

TEST(DisplayPatchGather, AClusteredFurnaceShowsItsExactRadiosityAtEveryVertex) {
    GatheredFurnace g = gathered_furnace();
    ASSERT_FALSE(g.display.traced.patch_gather.empty());
    const GatherTable& gather = g.display.traced.patch_gather;
    // A closed room: every ray meets a front, so each row's weights add up to 1.
    for (std::size_t d = 0; d < g.display.patch_count; ++d) {
        const double sum = std::accumulate(gather.weight.begin() + gather.row_begin[d],
                                           gather.weight.begin() + gather.row_begin[d + 1], 0.0);
        ASSERT_NEAR(sum, 1.0, 1e-3) << "display patch " << d;
    }
    EXPECT_LT(worst_error(vertex_radiance(g.display, g.solved->radiosity), 2.0), 2e-3);
}

TEST(DisplayPatchGather, WhileBouncesAreSteppedAPatchShowsTheBouncesOfItsStep) {
    // After k Jacobi steps from B = E the furnace holds B_k = E (1 + ρ + ... + ρ^k) everywhere. Stepped, the
    // display gathers the step before and shows B_3 = 1.875; gathering the latest shows one bounce more,
    // E + ρ B_3 = 1.9375.
    GatheredFurnace g = gathered_furnace();
    const std::size_t n = g.solved->radiosity.size();
    const std::vector<glm::dvec3> b2(n, glm::dvec3(1.75)), b3(n, glm::dvec3(1.875));
    EXPECT_LT(worst_error(stepped_vertex_radiance(g.display, b3, b2), 1.875), 2e-3);
    EXPECT_LT(worst_error(vertex_radiance(g.display, b3), 1.9375), 2e-3);
}

TEST(DisplayPatchGather, BelowTheFewestRaysPerPatchTheDisplayKeepsTheLeavesMeans) {
    const GatheredFurnace g = gathered_furnace(kPatchGatherMinRays - 1);
    EXPECT_TRUE(g.display.traced.patch_gather.empty());
}

}  // namespace
}  // namespace rad
