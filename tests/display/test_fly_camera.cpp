// The viewer's camera as maths: movement is speed × time whatever the frame rate, looking keeps "up".
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "rad/camera/fly_camera.hpp"

namespace rad {
namespace {

const Camera kStart{{1, 2, 3}, {1, 2, 0}, {0, 1, 0}, 40.0};  // looking along -z

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-9) {
    EXPECT_NEAR(glm::length(a - b), 0.0, tolerance) << "(" << a.x << ", " << a.y << ", " << a.z << ")";
}

TEST(FlyCamera, StartsWhereTheSceneCameraIs) {
    const FlyCamera camera(kStart, 2.0);
    expect_near(camera.camera().eye, kStart.eye);
    expect_near(camera.forward(), {0, 0, -1});
    expect_near(camera.right(), {1, 0, 0});
    EXPECT_EQ(camera.camera().fov_degrees, 40.0);
}

TEST(FlyCamera, AKeyHeldMovesSpeedTimesTime) {
    FlyCamera camera(kStart, 2.5);
    camera.move({1, 0, 0}, 0.8);  // W for 0.8 s at 2.5 units/s
    expect_near(camera.camera().eye, kStart.eye + glm::dvec3(0, 0, -2.0));
    camera.move({0, -1, 0}, 0.4);  // A
    camera.move({0, 0, 1}, 1.2);   // E
    expect_near(camera.camera().eye, kStart.eye + glm::dvec3(-1.0, 3.0, -2.0));
}

TEST(FlyCamera, DistanceDoesNotDependOnTheFrameRate) {
    FlyCamera fast(kStart, 3.0), slow(kStart, 3.0);
    for (int i = 0; i < 144; ++i) fast.move({1, 1, 0}, 1.0 / 144.0);
    for (int i = 0; i < 24; ++i) slow.move({1, 1, 0}, 1.0 / 24.0);
    expect_near(fast.camera().eye, slow.camera().eye, 1e-9);
}

TEST(FlyCamera, LookingTurnsAndPitchStopsShortOfVertical) {
    FlyCamera camera(kStart, 1.0);
    const double quarter_turn = (3.14159265358979 / 2) / FlyCamera::kRadiansPerPixel;
    camera.look(quarter_turn, 0.0);  // drag right by a quarter turn: now looking along +x
    expect_near(camera.forward(), {1, 0, 0}, 1e-6);
    camera.look(0.0, -10 * quarter_turn);  // far up
    EXPECT_LT(camera.forward().y, 1.0);
    EXPECT_GT(camera.forward().y, 0.99);
    EXPECT_NEAR(glm::length(camera.right()), 1.0, 1e-12);
    camera.reset();
    expect_near(camera.forward(), {0, 0, -1});
}

TEST(FlyCamera, ScrollChangesSpeedAndOrbitKeepsDistance) {
    FlyCamera camera(kStart, 1.0);
    camera.scroll_speed(2.0);
    EXPECT_DOUBLE_EQ(camera.speed(), 1.5625);
    const glm::dvec3 centre(1, 2, 0);
    camera.orbit(centre, 200.0, 50.0);
    EXPECT_NEAR(glm::length(camera.camera().eye - centre), 3.0, 1e-9);
    expect_near(camera.forward(), glm::normalize(centre - camera.camera().eye), 1e-9);
}

TEST(FlyCamera, AKeptViewIsWhereGoingToItReturns) {
    FlyCamera camera(kStart, 1.0);
    camera.move({1, 1, 0}, 2.0);
    camera.look(120.0, -40.0);
    const Camera kept = camera.camera();
    camera.reset();
    camera.go_to(kept);
    expect_near(camera.camera().eye, kept.eye, 1e-12);
    expect_near(camera.forward(), glm::normalize(kept.target - kept.eye), 1e-12);
}

}  // namespace
}  // namespace rad
