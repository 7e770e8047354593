// The Embree interface: front and back faces, occlusion, misses, shared buffers and error routing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "form_factor_test_scenes.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {
namespace {

// Surface 0 (patch 0) at y = 0 faces up; surface 1 (patch 1) at y = 1 faces down.
PatchMesh two_squares() {
    return test::mesh(test::parallel_rectangles(1, 1, 1), 1.0);
}

TEST(RayScene, RaysReachFrontFacesAndAreBlockedByBackFaces) {
    const PatchMesh mesh = two_squares();
    ASSERT_EQ(mesh.size(), 2u);
    ASSERT_GT(mesh.patches[0].normal.y, 0.0);
    const RayScene scene(mesh);
    const std::vector<Ray> rays = {
        {{0.5f, 0.5f, 0.5f}, 0.0f, {0, 1, 0}, 1e30f},   // up, onto the front of patch 1
        {{0.5f, 0.5f, 0.5f}, 0.0f, {0, -1, 0}, 1e30f},  // down, onto the front of patch 0
        {{0.5f, 2.0f, 0.5f}, 0.0f, {0, -1, 0}, 1e30f},  // from above, onto the back of patch 1
        {{0.5f, -1.f, 0.5f}, 0.0f, {0, 1, 0}, 1e30f},   // from below, onto the back of patch 0
        {{0.5f, 0.5f, 0.5f}, 0.0f, {1, 0, 0}, 1e30f},   // sideways, out of the scene
    };
    std::vector<RayHit> hits(rays.size());
    scene.intersect(rays, hits);
    EXPECT_EQ(hits[0].patch, 1u);
    EXPECT_NEAR(hits[0].t, 0.5f, 1e-6f);
    EXPECT_EQ(hits[1].patch, 0u);
    EXPECT_EQ(hits[2].patch, RayHit::kBackFace);
    EXPECT_NEAR(hits[2].t, 1.0f, 1e-6f);
    EXPECT_EQ(hits[3].patch, RayHit::kBackFace);
    EXPECT_EQ(hits[4].patch, RayHit::kMissed);
    // `met` names the patch met, whichever side.
    const std::uint32_t met[] = {1u, 0u, 1u, 0u, RayHit::kMissed};
    for (std::size_t k = 0; k < rays.size(); ++k) EXPECT_EQ(hits[k].met, met[k]) << "ray " << k;
}

TEST(RayScene, OcclusionCountsBothSidesAndRespectsTheSegment) {
    const PatchMesh mesh = two_squares();
    const RayScene scene(mesh);
    const std::vector<Ray> rays = {
        {{0.5f, 2.0f, 0.5f}, 0.0f, {0, -1, 0}, 1e30f},  // meets the back of patch 1: blocked
        {{0.5f, 0.5f, 0.5f}, 0.0f, {0, 1, 0}, 0.4f},    // stops short of patch 1
        {{0.5f, 0.5f, 0.5f}, 0.0f, {0, 1, 0}, 0.6f},    // reaches patch 1
        {{0.5f, 0.5f, 0.5f}, 0.0f, {1, 0, 0}, 1e30f},   // nothing in the way
        {{0.5f, 0.5f, 0.5f}, 0.6f, {0, 1, 0}, 1e30f},   // starts past patch 1
    };
    std::vector<std::uint8_t> blocked(rays.size(), 7);
    scene.occluded(rays, blocked);
    EXPECT_EQ(blocked, (std::vector<std::uint8_t>{1, 0, 1, 0, 0}));
}

// A roof of one surface: two quads meeting at a ridge along z at (x, y) = (0, 1), one sloping down to each
// side and facing out (up-left, up-right). A ray running along y = 1 crosses the ridge edge, meeting the
// front of one slope and the back of the other at the same distance.
PatchMesh ridge() {
    PatchMesh mesh;
    mesh.points = {{-1, 0, 0}, {-1, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 0, 1}, {1, 0, 0}};
    mesh.corners = {{0, 1, 2, 3}, {3, 2, 4, 5}};
    const double s = 1.0 / std::sqrt(2.0);
    mesh.patches = {Patch{0, 0, std::sqrt(2.0), {-0.5, 0.5, 0.5}, {-s, s, 0}},
                    Patch{0, 1, std::sqrt(2.0), {0.5, 0.5, 0.5}, {s, s, 0}}};
    mesh.surface_begin = {0, 2};
    return mesh;
}

// The ray touched the roof's outside: it reaches the front, whichever of the two Embree met first.
TEST(RayScene, ARayAlongARidgeReachesTheFrontItGrazes) {
    const PatchMesh mesh = ridge();
    const RayScene scene(mesh);
    std::vector<Ray> rays;
    for (int k = 1; k < 200; ++k) {
        const double z = k / 200.0;
        rays.push_back({{-2.0, 1.0, z}, 0.0f, {1, 0, 0}, 1e30f});  // front of patch 0, back of patch 1
        rays.push_back({{2.0, 1.0, z}, 0.0f, {-1, 0, 0}, 1e30f});  // front of patch 1, back of patch 0
    }
    std::vector<RayHit> hits(rays.size());
    scene.intersect(rays, hits);
    for (std::size_t k = 0; k < rays.size(); ++k) {
        // A hit or a miss at the edge both happen (Embree's edge rule); a back never.
        EXPECT_NE(hits[k].patch, RayHit::kBackFace) << "ray " << k;
        if (hits[k].patch != RayHit::kMissed) {
            EXPECT_EQ(hits[k].patch, k % 2 == 0 ? 0u : 1u) << "ray " << k;
            EXPECT_NEAR(hits[k].t, 2.0f, 1e-5f) << "ray " << k;
        }
    }
}

// Batches longer than Embree's stream of 64 rays, with a remainder, come back in order.
TEST(RayScene, LongBatchesKeepTheirOrder) {
    const PatchMesh mesh = two_squares();
    const RayScene scene(mesh);
    std::vector<Ray> rays;
    for (int k = 0; k < 150; ++k) {
        const float x = 0.1f + 0.8f * static_cast<float>(k) / 150.0f;
        rays.push_back({{x, 0.5f, 0.5f}, 0.0f, {0, k % 3 == 0 ? 1.0f : -1.0f, 0}, 1e30f});
    }
    std::vector<RayHit> hits(rays.size());
    scene.intersect(rays, hits);
    for (int k = 0; k < 150; ++k) EXPECT_EQ(hits[k].patch, k % 3 == 0 ? 1u : 0u) << "ray " << k;
}

// Embree sees the scene in its own normalized frame, so the same rays in a scene moved and scaled by any
// factor meet the same patches at the same parameters t.
TEST(RayScene, TheSameRaysInAMovedAndScaledSceneHitAlike) {
    const PatchMesh mesh = two_squares();
    PatchMesh moved = mesh;
    const glm::dvec3 shift(1e4, -3e3, 7e2);
    const double scale = 1e-3;
    for (glm::dvec3& p : moved.points) p = p * scale + shift;
    const RayScene scene(mesh), moved_scene(moved);
    std::vector<Ray> rays, moved_rays;
    for (int k = 0; k < 400; ++k) {
        // Grazing rays towards the squares' edges, where float rounding decides.
        const double a = 0.01 * k;
        const Ray ray{{0.5, 0.5, 0.5}, 0.0f, {std::cos(a), std::sin(3.0 * a), std::sin(a)}, 1e30f};
        rays.push_back(ray);
        moved_rays.push_back({ray.origin * scale + shift, 0.0f, ray.direction * scale, 1e30f});
    }
    std::vector<RayHit> hits(rays.size()), moved_hits(rays.size());
    scene.intersect(rays, hits);
    moved_scene.intersect(moved_rays, moved_hits);
    for (std::size_t k = 0; k < rays.size(); ++k) {
        EXPECT_EQ(hits[k].patch, moved_hits[k].patch) << "ray " << k;
        if (hits[k].patch != RayHit::kMissed) {
            EXPECT_NEAR(hits[k].t, moved_hits[k].t, 1e-6f * hits[k].t) << "ray " << k;
        }
    }
}

TEST(RayScene, EmbreeErrorsBecomeExceptionsWithEmbreesMessage) {
    const PatchMesh mesh = two_squares();
    try {
        RayScene scene(mesh, "quad_accel=no_such_structure");
        FAIL() << "Embree accepted an unknown acceleration structure";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("Embree: invalid argument"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no_such_structure"), std::string::npos) << e.what();
    }
    EXPECT_THROW(RayScene(mesh, "threads=not_a_number"), std::runtime_error);
}

}  // namespace
}  // namespace rad
