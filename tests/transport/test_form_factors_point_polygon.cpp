// Lambert's point-to-polygon factor against docs/analytic.md, and the clipping that keeps it valid.
#include <gtest/gtest.h>

#include <vector>

#include "rad/geometry/point_polygon_factor.hpp"

namespace rad {
namespace {

// Counter-clockwise seen from below, so the front faces down towards the point.
std::vector<glm::dvec3> facing_down(double x0, double x1, double y0, double y1, double z) {
    return {{x0, y0, z}, {x0, y1, z}, {x1, y1, z}, {x1, y0, z}};
}

constexpr double kTolerance = 1e-6;  // the table gives six digits

TEST(PointPolygonFactor, UnitSquareAboveACorner) {
    EXPECT_NEAR(point_polygon_factor({0, 0, 0}, {0, 0, 1}, facing_down(0, 1, 0, 1, 1)), 0.138532, kTolerance);
}

TEST(PointPolygonFactor, TwoByTwoSquareAboveItsCentre) {
    EXPECT_NEAR(point_polygon_factor({0, 0, 0}, {0, 0, 1}, facing_down(-1, 1, -1, 1, 1)), 0.554126,
                kTolerance);
}

TEST(PointPolygonFactor, PerpendicularWall) {
    // The wall x = 1, y and z in [0, 1], facing -x (towards the point).
    const std::vector<glm::dvec3> wall = {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}};
    EXPECT_NEAR(point_polygon_factor({0, 0, 0}, {0, 0, 1}, wall), 0.055734, kTolerance);
}

TEST(PointPolygonFactor, BackSideIsNegative) {
    std::vector<glm::dvec3> square = facing_down(0, 1, 0, 1, 1);
    std::reverse(square.begin(), square.end());
    EXPECT_NEAR(point_polygon_factor({0, 0, 0}, {0, 0, 1}, square), -0.138532, kTolerance);
}

TEST(PointPolygonFactor, ClippingKeepsOnlyWhatLiesInFront) {
    // A vertical wall through the tangent plane z = 0: only its upper half can be seen from the origin.
    const ConvexPolygon wall =
        make_convex_polygon(std::vector<glm::dvec3>{{1, 0, -1}, {1, 0, 1}, {1, 1, 1}, {1, 1, -1}});
    const ConvexPolygon upper = clip_to_front(wall, {0, 0, 0}, {0, 0, 1});
    ASSERT_EQ(upper.count, 4u);
    for (const glm::dvec3& p : upper.span()) EXPECT_GE(p.z, 0.0);
    EXPECT_NEAR(point_polygon_factor({0, 0, 0}, {0, 0, 1}, upper.span()), 0.055734, kTolerance);
    EXPECT_TRUE(clip_to_front(wall, {0, 0, 2}, {0, 0, 1}).empty());
    // A polygon in the plane itself is not in front of it.
    const ConvexPolygon flat = make_convex_polygon(facing_down(0, 1, 0, 1, 0));
    EXPECT_TRUE(clip_to_front(flat, {0, 0, 0}, {0, 0, 1}).empty());
}

}  // namespace
}  // namespace rad
