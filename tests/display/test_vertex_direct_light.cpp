// The emitters' direct light at display vertices (add_vertex_direct_light), on a shadow edge with a closed
// form (assets/hard/shadow_edge.obj): a floor lit by a square light, half of it shaded by a plate. The
// floor's radiosity is its direct light alone, so at every floor vertex the shown radiance has an exact
// value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>

#include "display/vertex_direct_light.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/geometry/point_polygon_factor.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

const std::string kShadowEdge = std::string(RAD_SOURCE_DIR) + "/assets/hard/shadow_edge.obj";

// L = ρ E F / π at floor point p, F the factor of the part of the light the plate leaves visible; E = π.
double exact_radiance(const glm::vec3& p) {
    const double x0 = std::max(-0.1, 0.06 - static_cast<double>(p.x));
    if (x0 >= 0.1) return 0.0;
    const glm::dvec3 light[4] = {{x0, 0.5, -0.1}, {0.1, 0.5, -0.1}, {0.1, 0.5, 0.1}, {x0, 0.5, 0.1}};
    return 0.5 * point_polygon_factor(glm::dvec3(p), {0.0, 1.0, 0.0}, light);
}

// E per patch, from its surface's material.
std::vector<glm::dvec3> emitted_radiosity(const Scene& scene, const PatchMesh& patches) {
    std::vector<glm::dvec3> emitted(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q)
        emitted[q] = scene.surfaces[patches.patches[q].surface].material.emitted_radiosity();
    return emitted;
}

struct Shown {
    std::unique_ptr<test::SolvedScene> solved;
    DisplayMesh display;
};

// The scene solved at `patch_size`, its display mesh with the direct light at the vertices or without;
// `split`: along shadow edges; `keep`: each patch's mean.
Shown show(Scene scene, double patch_size, bool direct_at_vertices, bool split = true, bool keep = true) {
    Shown s;
    s.solved = test::solve_scene(std::move(scene), Subdivision::uniform, patch_size);
    const Transport& t = *s.solved->system.transport;
    const PatchMesh& patches = *s.solved->system.patches;
    s.display = build_display_mesh(patches);
    if (!direct_at_vertices) return s;
    const std::vector<glm::dvec3> emitted = emitted_radiosity(s.solved->scene, patches);
    std::vector<glm::dvec3> direct(t.size());
    t.gather(emitted, direct);
    for (std::size_t q = 0; q < direct.size(); ++q) direct[q] *= t.reflectance[q];
    const RayScene rays(patches);
    add_vertex_direct_light(s.display, {.patches = &patches,
                                        .rays = &rays,
                                        .emitted = emitted,
                                        .emission = t.emission,
                                        .reflectance = t.reflectance,
                                        .area = t.area,
                                        .patch_direct = direct,
                                        .seed = 1,
                                        .keep_patch_means = keep,
                                        .split_shadow_edges = split});
    return s;
}

struct FloorErrors {
    double penumbra_rms =
        0.0;                 // of the drawn image within 0.15 of the plate's edge, relative to the lit value
    double umbra_max = 0.0;  // the largest radiance shown where the light is hidden (x < -0.04)
    double mean_rms = 0.0;   // the RMS error of the floor patches' drawn means, relative to the lit value
};

// The drawn radiance over one triangle at barycentric (u, v): linear between its vertices' values.
double drawn_at(const std::vector<glm::vec3>& shown, const glm::uvec3& c, double u, double v) {
    return (1.0 - u - v) * shown[c[0]].y + u * shown[c[1]].y + v * shown[c[2]].y;
}

FloorErrors floor_errors(const Shown& s) {
    const std::vector<glm::vec3> shown = vertex_radiance(s.display, s.solved->radiosity);
    const double lit = exact_radiance({0.2f, 0.0f, 0.0f});
    FloorErrors e;
    for (std::size_t v = 0; v < s.display.vertex_count(); ++v) {
        const glm::vec3& p = s.display.positions[v];
        if (std::abs(p.y) > 1e-6f || s.display.normals[v].y < 0.99f) continue;  // the floor's vertices
        if (p.x < -0.04f) e.umbra_max = std::max(e.umbra_max, static_cast<double>(shown[v].y));
    }
    // The drawn image's error, integrated over the floor near the plate's edge: each floor triangle is
    // sampled at the centres of its 8 x 8 sub-triangles, as a picture of it would be.
    constexpr int kSteps = 8;
    double sum = 0.0, covered = 0.0;
    for (std::size_t t = 0; t < s.display.triangles.size(); ++t) {
        const glm::uvec3& c = s.display.triangles[t];
        const glm::dvec3 a(s.display.positions[c[0]]), b(s.display.positions[c[1]]),
            d(s.display.positions[c[2]]);
        const glm::dvec3 n = glm::cross(b - a, d - a);
        if (std::abs(a.y) > 1e-6 || !(n.y > 0.0)) continue;  // the floor's triangles
        const double piece = 0.5 * glm::length(n) / (kSteps * kSteps);
        for (int i = 0; i < kSteps; ++i) {
            for (int j = 0; i + j < kSteps; ++j) {
                for (int flip = 0; flip < (i + j + 1 < kSteps ? 2 : 1); ++flip) {
                    const double u = (i + (flip ? 2.0 : 1.0) / 3.0) / kSteps;
                    const double v = (j + (flip ? 2.0 : 1.0) / 3.0) / kSteps;
                    const glm::dvec3 p = a + u * (b - a) + v * (d - a);
                    if (std::abs(p.x) > 0.45 || std::abs(p.z) > 0.45 || std::abs(p.x - 0.03) > 0.15) continue;
                    const double error = (drawn_at(shown, c, u, v) - exact_radiance(glm::vec3(p))) / lit;
                    sum += piece * error * error;
                    covered += piece;
                }
            }
        }
    }
    EXPECT_GT(covered, 0.1);
    e.penumbra_rms = std::sqrt(sum / covered);
    // What each floor patch's triangles show on average, against the radiance it holds.
    std::vector<double> drawn(s.display.patch_count, 0.0), area(s.display.patch_count, 0.0);
    for (std::size_t t = 0; t < s.display.triangles.size(); ++t) {
        const glm::uvec3& c = s.display.triangles[t];
        const glm::vec3 &a = s.display.positions[c[0]], &b = s.display.positions[c[1]],
                        &d = s.display.positions[c[2]];
        const double triangle = 0.5 * glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(d - a)));
        drawn[s.display.triangle_patch[t]] +=
            triangle * (shown[c[0]].y + shown[c[1]].y + shown[c[2]].y) / 3.0;
        area[s.display.triangle_patch[t]] += triangle;
    }
    const PatchMesh& patches = *s.solved->system.patches;
    double squares = 0.0;
    for (std::uint32_t q = patches.surface_begin[0]; q < patches.surface_begin[1]; ++q) {
        const double held = s.solved->radiosity[q].y / std::numbers::pi;
        squares += std::pow((drawn[q] / area[q] - held) / lit, 2);
    }
    e.mean_rms = std::sqrt(squares / (patches.surface_begin[1] - patches.surface_begin[0]));
    return e;
}

TEST(VertexDirectLight, TheShadowEdgeIsSharpAtTheVertices) {
    const FloorErrors with = floor_errors(show(load_scene(kShadowEdge), 0.1, true));
    const FloorErrors without = floor_errors(show(load_scene(kShadowEdge), 0.1, false));
    std::printf("penumbra RMS %.4f with, %.4f without; umbra max %.3g / %.3g; patch means RMS %.4f / %.4f\n",
                with.penumbra_rms, without.penumbra_rms, with.umbra_max, without.umbra_max, with.mean_rms,
                without.mean_rms);
    EXPECT_LT(with.penumbra_rms, without.penumbra_rms);
    EXPECT_EQ(with.umbra_max, 0.0);  // every ray blocked: no light, exactly
    EXPECT_LT(with.mean_rms, without.mean_rms);
}

// Splitting the triangles where the light steps draws the penumbra at finer than the patches: closer to the
// exact light where vertices show their own value, and each patch's drawn mean closer to what it holds
// where means are kept. The vertices it adds are at most as many as the mesh had.
TEST(VertexDirectLight, SplittingAlongTheShadowEdgeDrawsItCloser) {
    const Shown split = show(load_scene(kShadowEdge), 0.1, true, true, false);
    const Shown whole = show(load_scene(kShadowEdge), 0.1, true, false, false);
    const FloorErrors exact_split = floor_errors(split), exact_whole = floor_errors(whole);
    const FloorErrors kept_split = floor_errors(show(load_scene(kShadowEdge), 0.1, true, true, true));
    const FloorErrors kept_whole = floor_errors(show(load_scene(kShadowEdge), 0.1, true, false, true));
    std::printf("vertices %zu split, %zu not; penumbra RMS %.4f / %.4f; patch means RMS (kept) %.4f / %.4f\n",
                split.display.vertex_count(), whole.display.vertex_count(), exact_split.penumbra_rms,
                exact_whole.penumbra_rms, kept_split.mean_rms, kept_whole.mean_rms);
    EXPECT_GT(split.display.vertex_count(), whole.display.vertex_count());
    EXPECT_LE(split.display.vertex_count(), 2 * whole.display.vertex_count());
    EXPECT_LT(exact_split.penumbra_rms, 0.8 * exact_whole.penumbra_rms);
    EXPECT_EQ(exact_split.umbra_max, 0.0);
    EXPECT_LT(kept_split.mean_rms, 0.8 * kept_whole.mean_rms);
}

TEST(VertexDirectLight, ShowsOnlyWhatTheRadiosityHoldsOfTheDirectLight) {
    Shown s = show(load_scene(kShadowEdge), 0.1, true);
    ASSERT_FALSE(s.display.light.direct.vertex.empty());
    EXPECT_TRUE(draws_vertex_direct_light(*s.solved->system.patches, s.display.light.direct.emission));
    const Transport& t = *s.solved->system.transport;
    EXPECT_EQ(direct_light_share(s.display, t.emission), 0.0);
    EXPECT_NEAR(direct_light_share(s.display, s.solved->radiosity), 1.0, 1e-9);
    // Before any bounce the vertices show the emission alone, as without direct light at vertices.
    DisplayMesh plain = s.display;
    plain.light.direct = {};
    EXPECT_EQ(vertex_radiance(s.display, t.emission), vertex_radiance(plain, t.emission));
    // The floor's light is all direct: a view of the first bounce alone (share 1) shows it as the whole
    // solution does.
    const std::vector<glm::vec3> first = vertex_radiance(s.display, s.display.light.direct.patch, 1.0);
    const std::vector<glm::vec3> whole = vertex_radiance(s.display, s.solved->radiosity);
    int floor_vertices = 0;
    for (std::size_t v = 0; v < s.display.vertex_count(); ++v) {
        if (std::abs(s.display.positions[v].y) > 1e-6f || s.display.normals[v].y < 0.99f) continue;
        EXPECT_NEAR(first[v].y, whole[v].y, 1e-6 + 1e-4 * whole[v].y);
        ++floor_vertices;
    }
    EXPECT_GT(floor_vertices, 100);
}

TEST(VertexDirectLight, LeavesSourcesAsLargeAsAFurnaceToThePatches) {
    // Every surface of the furnace emits: its light is smooth, and the vertices keep the patches' values.
    // (It returns before the per-patch values are read, so zeros stand in for a solution.)
    const Scene scene = make_builtin_scene("furnace-1k");
    const PatchMesh patches = build_patches(scene, {});
    DisplayMesh display = build_display_mesh(patches);
    const std::vector<glm::dvec3> emitted = emitted_radiosity(scene, patches);
    const std::vector<glm::dvec3> zeros(patches.size(), glm::dvec3(0.0));
    const std::vector<double> area(patches.size(), 1.0);
    const RayScene rays(patches);
    add_vertex_direct_light(display, {.patches = &patches,
                                      .rays = &rays,
                                      .emitted = emitted,
                                      .emission = emitted,
                                      .reflectance = zeros,
                                      .area = area,
                                      .patch_direct = zeros});
    EXPECT_TRUE(display.light.direct.vertex.empty());
    EXPECT_EQ(direct_light_share(display, emitted), 0.0);
    EXPECT_FALSE(draws_vertex_direct_light(patches, emitted));
}

// 400 lamps of 4 cm in an empty room (assets/hard/many_lights.obj): more emitter patches than are drawn from
// directly, so they are drawn in chunks first (the exact sum that points seeing every lamp take is turned off
// here, a budget of 0, to test the draws). Nothing blocks them, so the exact value at a floor point is the
// sum of every lamp's point-to-polygon factor times its E.
TEST(VertexDirectLight, ManySmallLampsAreDrawnInChunksWithoutBias) {
    const Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/many_lights.obj");
    const PatchMesh patches = build_patches(scene, {});
    const std::vector<glm::dvec3> emitted = emitted_radiosity(scene, patches);
    ASSERT_GT(std::count_if(emitted.begin(), emitted.end(), [](const glm::dvec3& e) { return e.y > 0.0; }),
              64);
    std::vector<glm::dvec3> points, normals;
    for (int i = 0; i < 12; ++i)
        for (int k = 0; k < 12; ++k) {
            points.emplace_back(0.2 + 0.3 * i, 1e-4, 0.2 + 0.3 * k);
            normals.emplace_back(0.0, 1.0, 0.0);
        }
    const RayScene rays(patches);
    const std::vector<glm::dvec3> estimate =
        direct_irradiance_at(patches, rays, emitted, points, normals, 1, 0.0);
    double sum = 0.0, exact_sum = 0.0, worst = 0.0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        double exact = 0.0;
        for (std::size_t q = 0; q < patches.size(); ++q) {
            if (!(emitted[q].y > 0.0)) continue;
            glm::dvec3 corners[4];
            for (int c = 0; c < 4; ++c) corners[c] = patches.points[patches.corners[q][c]];
            exact += emitted[q].y * point_polygon_factor(points[p], normals[p], corners);
        }
        sum += estimate[p].y;
        exact_sum += exact;
        worst = std::max(worst, std::abs(estimate[p].y / exact - 1.0));
    }
    std::printf("mean %.5f against %.5f exact, worst point %.4f\n", sum / points.size(),
                exact_sum / points.size(), worst);
    EXPECT_NEAR(sum / exact_sum, 1.0, 0.005);
    EXPECT_LT(worst, 0.02);
}

// A luminous ceiling of 256 patches (builtin:cube): beside it the patches' factors differ far more than
// their weights say, and 16 draws over them streaked the walls (35 % off at the worst of these points). A
// point that sees all of it takes the exact sum: the factor of the whole ceiling, to rounding.
TEST(VertexDirectLight, APointSeeingAWholeLuminousCeilingTakesItsExactFactor) {
    const Scene scene = make_builtin_scene("cube");
    const PatchMesh patches = build_patches(scene, {});
    const std::vector<glm::dvec3> emitted = emitted_radiosity(scene, patches);
    ASSERT_GT(std::count_if(emitted.begin(), emitted.end(), [](const glm::dvec3& e) { return e.y > 0.0; }),
              64);
    std::vector<glm::dvec3> points, normals;
    for (int i = 1; i < 20; ++i) {
        points.emplace_back(0.05 * i, 0.97, 1e-4);  // the back wall just below the ceiling
        normals.emplace_back(0.0, 0.0, 1.0);
    }
    const RayScene rays(patches);
    const std::vector<glm::dvec3> shown = direct_irradiance_at(patches, rays, emitted, points, normals);
    const glm::dvec3 ceiling[4] = {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}};
    const double e = emitted[std::distance(emitted.begin(), std::find_if(emitted.begin(), emitted.end(),
                                                                         [](auto& x) { return x.y > 0.0; }))]
                         .y;
    const std::vector<glm::dvec3> drawn =
        direct_irradiance_at(patches, rays, emitted, points, normals, 1, 0.0);
    double worst_drawn = 0.0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        const double exact = e * std::abs(point_polygon_factor(points[p], normals[p], ceiling));
        EXPECT_NEAR(shown[p].y / exact, 1.0, 1e-4) << "x = " << points[p].x;
        worst_drawn = std::max(worst_drawn, std::abs(drawn[p].y / exact - 1.0));
    }
    std::printf("the draws alone: worst point %.4f from the exact factor\n", worst_drawn);
}

TEST(VertexDirectLight, RefusesArraysOfAnotherSize) {
    Shown s = show(load_scene(kShadowEdge), 0.1, false);
    const PatchMesh& patches = *s.solved->system.patches;
    const RayScene rays(patches);
    const std::vector<glm::dvec3> short_array(2);
    EXPECT_THROW(
        add_vertex_direct_light(s.display, {.patches = &patches, .rays = &rays, .emitted = short_array}),
        std::invalid_argument);
}

}  // namespace
}  // namespace rad
