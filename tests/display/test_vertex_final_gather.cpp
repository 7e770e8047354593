// The final gather at display vertices (add_vertex_final_gather): a vertex beside a wall of known radiosity
// shows the closed-form point factor to it, and a furnace shows its exact radiosity at every vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "display/vertex_final_gather.hpp"
#include "form_factor_test_scenes.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/geometry/point_polygon_factor.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

struct Gathered {
    std::unique_ptr<test::SolvedScene> solved;
    DisplayMesh display;
};

// The display of `solved`'s patches with its final gather; `emission` and `source` per patch.
Gathered gather(std::unique_ptr<test::SolvedScene> solved, const std::vector<glm::dvec3>& emission,
                const std::vector<glm::dvec3>& source, std::size_t budget = kFinalGatherRayBudget,
                bool near_surfaces_only = false) {
    Gathered g{std::move(solved), {}};
    const PatchMesh& patches = *g.solved->system.patches;
    g.display = build_display_mesh(patches);
    const RayScene rays(patches);
    add_vertex_final_gather(g.display, {.patches = &patches,
                                        .rays = &rays,
                                        .emission = emission,
                                        .reflectance = g.solved->system.transport->reflectance,
                                        .source = source,
                                        .ray_budget = budget,
                                        .near_surfaces_only = near_surfaces_only});
    return g;
}

// `scene` in uniform patches of 0.1, its display gathered near surfaces only, over no emission or source.
Gathered gathered_near_surfaces(Scene scene) {
    auto solved = test::solve_scene(std::move(scene), Subdivision::uniform, 0.1);
    const std::vector<glm::dvec3> zero(solved->system.patches->size(), glm::dvec3(0.0));
    return gather(std::move(solved), zero, zero, kFinalGatherRayBudget, true);
}

std::uint32_t vertex_surface(const DisplayMesh& display, const PatchMesh& patches, std::size_t v) {
    return patches.patches[display.weight_patch[display.weight_begin[v]]].surface;
}

TEST(FinalGather, AVertexBesideABrightFloorShowsItsPointFactor) {
    // builtin:perpendicular: a unit floor (surface 0) and a unit wall (surface 1, ρ = 0.5) sharing an edge.
    // With the floor at B = 1 and nothing else lit, a wall vertex shows ρ F(x → floor) / π, F the closed-form
    // point-to-polygon factor; the wall's own patches (B = 0 here) take no part.
    auto solved = test::solve_scene(make_perpendicular_squares(), Subdivision::uniform, 0.25);
    const PatchMesh& patches = *solved->system.patches;
    const std::size_t n = patches.size();
    const std::vector<glm::dvec3> zero(n, glm::dvec3(0.0));
    Gathered g = gather(std::move(solved), zero, zero);
    ASSERT_FALSE(g.display.traced.gather.empty());
    std::vector<glm::dvec3> radiosity(n, glm::dvec3(0.0));
    for (std::size_t q = 0; q < n; ++q)
        if (patches.patches[q].surface == 0) radiosity[q] = glm::dvec3(1.0);
    const std::vector<glm::vec3> shown = vertex_radiance(g.display, radiosity);
    const glm::dvec3 floor[4] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}};
    double sum = 0.0, worst = 0.0;
    int counted = 0;
    for (std::size_t v = 0; v < g.display.vertex_count(); ++v) {
        if (vertex_surface(g.display, patches, v) != 1) continue;
        // On the shared edge (y = 0) the closed form degenerates to 0; the light there is its limit from
        // above, where the vertex's rays leave. At the edge's ends that limit depends on the way in (a
        // quarter of the hemisphere straight up, more along the diagonal the rays leave by): left out.
        glm::dvec3 x(g.display.positions[v]);
        if (x.y < 1e-9 && (x.z < 1e-9 || x.z > 1.0 - 1e-9)) continue;
        x.y = std::max(x.y, 1e-6);
        const double exact = 0.5 * point_polygon_factor(x, {1, 0, 0}, floor) / std::numbers::pi;
        ASSERT_GT(exact, 0.0);
        const double error = std::abs(static_cast<double>(shown[v].x) - exact) / exact;
        sum += error;
        worst = std::max(worst, error);
        ++counted;
    }
    ASSERT_GT(counted, 20);
    // 256 stratified rays per vertex, each ray's share 1/256 of the hemisphere: the strata the floor's
    // outline crosses are the noise (3.0 % on average over these 23 vertices, 13 % at the worst).
    EXPECT_LT(sum / counted, 0.04);
    EXPECT_LT(worst, 0.2);
    // Without the gather the wall shows its own patches: nothing.
    const std::vector<glm::vec3> patches_only = vertex_radiance(g.display, radiosity, {}, false);
    for (std::size_t v = 0; v < g.display.vertex_count(); ++v) {
        if (vertex_surface(g.display, patches, v) != 1) continue;
        EXPECT_EQ(patches_only[v].x, 0.0f);
    }
}

TEST(FinalGather, NearSurfacesOnlyTheFloorBesideTheWallGathers) {
    // builtin:perpendicular at patch size 0.1: a floor vertex farther than two patch sizes (0.2) from the
    // wall meets nothing that near and keeps its patches; one within half a patch size of it sends half its
    // rays into the wall, most of them nearer than 0.2, and gathers with kNearGatherRays rays.
    const Gathered g = gathered_near_surfaces(make_perpendicular_squares());
    ASSERT_FALSE(g.display.traced.gather.empty());
    const GatherTable& rows = g.display.traced.gather;
    int far = 0, near = 0;
    bool finer = false;
    for (std::size_t v = 0; v < g.display.vertex_count(); ++v) {
        if (vertex_surface(g.display, *g.solved->system.patches, v) != 0) continue;
        const double to_wall = g.display.positions[v].x;  // the wall stands at x = 0
        const std::uint32_t begin = rows.row_begin[v], end = rows.row_begin[v + 1];
        if (to_wall > 0.2 + 1e-9) {
            EXPECT_EQ(begin, end) << "vertex at x = " << to_wall;
            ++far;
        } else if (to_wall < 0.05) {
            ASSERT_LT(begin, end) << "vertex at x = " << to_wall;
            for (std::uint32_t k = begin; k < end; ++k) {
                const float rays = rows.weight[k] * kNearGatherRays;
                EXPECT_NEAR(rays, std::round(rays), 1e-3f);  // a whole number of the vertex's rays
                // A share that is no whole number of 256ths: more rays than the every-vertex gather's.
                if (std::abs(rays / 4.0f - std::round(rays / 4.0f)) > 0.1f) finer = true;
            }
            ++near;
        }
    }
    EXPECT_GT(far, 50);
    EXPECT_GT(near, 5);
    EXPECT_TRUE(finer);
}

TEST(FinalGather, NearSurfacesOnlyFacesSmallerThanAPatchMakeNoVertexGather) {
    // A 1 × 1 floor and a wall at x = 0 at patch size 0.1, and 5 × 5 squares 0.04 on a side hovering 0.03
    // over the floor's far part (x from 0.5 to 0.94), alternately facing down (the floor meets their fronts)
    // and up (their backs). A floor vertex under them meets a face well within two patch sizes, but one
    // smaller than its patch: light that varies on their spacing is more than samples at the vertices can
    // show (they would alias into bands), so it keeps its patches; beside the wall, a face larger than a
    // patch, a vertex gathers.
    test::TestSceneBuilder builder;
    builder.add("floor", {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
    builder.add("wall", {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});
    const double side = 0.04, y = 0.03;
    for (int i = 0; i < 5; ++i) {
        for (int k = 0; k < 5; ++k) {
            const double x = 0.5 + 0.1 * i, z = 0.1 + 0.2 * k;
            const std::string name = "square " + std::to_string(i) + "," + std::to_string(k);
            if ((i + k) % 2 == 0) {
                builder.add(name, {{x, y, z}, {x + side, y, z}, {x + side, y, z + side}, {x, y, z + side}});
            } else {
                builder.add(name, {{x, y, z}, {x, y, z + side}, {x + side, y, z + side}, {x + side, y, z}});
            }
        }
    }
    const Gathered g = gathered_near_surfaces(builder.build());
    ASSERT_FALSE(g.display.traced.gather.empty());
    const GatherTable& rows = g.display.traced.gather;
    int under = 0, beside_wall = 0;
    for (std::size_t v = 0; v < g.display.vertex_count(); ++v) {
        if (vertex_surface(g.display, *g.solved->system.patches, v) != 0) continue;
        const glm::vec3 x = g.display.positions[v];
        const bool gathers = rows.row_begin[v] < rows.row_begin[v + 1];
        if (x.x < 0.05f) {
            EXPECT_TRUE(gathers) << "vertex at x = " << x.x << ", z = " << x.z;
            ++beside_wall;
        } else if (x.x > 0.45f) {
            EXPECT_FALSE(gathers) << "vertex at x = " << x.x << ", z = " << x.z;
            ++under;
        }
    }
    EXPECT_GT(under, 40);
    EXPECT_GT(beside_wall, 5);
}

TEST(FinalGather, AClusteredFurnaceShowsItsExactRadiosityAtEveryVertex) {
    // Every face ρ = 0.5, E = 1: B = 2 everywhere, and every ray from a front meets a front.
    auto solved = test::solve_scene(make_furnace(1000), Subdivision::clustered);
    const std::vector<glm::dvec3> emission = solved->system.transport->emission;
    const std::vector<glm::dvec3> radiosity = solved->radiosity;
    const std::vector<glm::dvec3> zero(emission.size(), glm::dvec3(0.0));
    const Gathered g = gather(std::move(solved), emission, zero);
    ASSERT_FALSE(g.display.traced.gather.empty());
    const std::vector<glm::vec3> shown = vertex_radiance(g.display, radiosity);
    double worst = 0.0;
    for (const glm::vec3& l : shown)
        worst = std::max(worst, std::abs(static_cast<double>(l.y) * std::numbers::pi - 2.0) / 2.0);
    EXPECT_LT(worst, 2e-3);
}

TEST(FinalGather, BelowTheFewestRaysPerVertexTheDisplayKeepsItsPatches) {
    auto solved = test::solve_scene(make_perpendicular_squares(), Subdivision::uniform, 0.25);
    const std::vector<glm::dvec3> zero(solved->system.patches->size(), glm::dvec3(0.0));
    const std::size_t vertices = build_display_mesh(*solved->system.patches).vertex_count();
    const Gathered g = gather(std::move(solved), zero, zero, vertices * (kFinalGatherMinRays - 1));
    EXPECT_TRUE(g.display.traced.gather.empty());
}

TEST(FinalGather, ArraysOfAnotherSizeAreRefused) {
    auto solved = test::solve_scene(make_perpendicular_squares(), Subdivision::uniform, 0.25);
    const std::vector<glm::dvec3> short_array(1, glm::dvec3(0.0));
    EXPECT_THROW(gather(std::move(solved), short_array, short_array), std::invalid_argument);
}

}  // namespace
}  // namespace rad
