// Polygon helpers: area, the planar-convex test, and triangulation of what is not planar and convex.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "rad/geometry/polygon.hpp"

namespace rad {
namespace {

double triangles_area(const std::vector<glm::dvec3>& poly,
                      const std::vector<std::array<std::size_t, 3>>& tris) {
    double area = 0.0;
    for (const auto& t : tris)
        area += polygon_area(std::vector<glm::dvec3>{poly[t[0]], poly[t[1]], poly[t[2]]});
    return area;
}

TEST(Polygon, NewellNormalGivesAreaAndFrontSide) {
    const std::vector<glm::dvec3> square{{0, 0, 0}, {2, 0, 0}, {2, 3, 0}, {0, 3, 0}};
    EXPECT_DOUBLE_EQ(polygon_area(square), 6.0);
    EXPECT_EQ(glm::normalize(newell_normal(square)), glm::dvec3(0, 0, 1));
}

TEST(Polygon, PlanarConvexTest) {
    EXPECT_TRUE(is_planar_convex(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
    // Concave (an arrow head) and non-planar (one corner lifted) quads.
    EXPECT_FALSE(is_planar_convex(std::vector<glm::dvec3>{{0, 0, 0}, {2, 1, 0}, {0, 2, 0}, {0.5, 1, 0}}));
    EXPECT_FALSE(is_planar_convex(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}}));
    // Collinear corners make a degenerate corner, not a convex one.
    EXPECT_FALSE(is_planar_convex(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1, 1, 0}}));
}

// Polygons that turn the same way at every corner but wind twice (found by fuzz_obj: OpenMesh asserts on a
// face that repeats a vertex).
TEST(Polygon, PolygonsThatWindTwiceAreNotConvex) {
    const std::vector<glm::dvec3> triangle_twice{{0, 0, 1}, {1, 0, 1}, {1, 0, 0},
                                                 {0, 0, 1}, {1, 0, 1}, {0, 0, 0}};
    EXPECT_FALSE(is_planar_convex(triangle_twice));
    std::vector<glm::dvec3> pentagram;
    for (int k = 0; k < 5; ++k) {
        const double angle = 2.0 * std::numbers::pi * 2 * k / 5;  // every second corner of a pentagon
        pentagram.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    }
    EXPECT_FALSE(is_planar_convex(pentagram));
    std::vector<glm::dvec3> pentagon;
    for (int k = 0; k < 5; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / 5;
        pentagon.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    }
    EXPECT_TRUE(is_planar_convex(pentagon));
}

TEST(Polygon, ConcavePolygonIsTriangulatedWithoutOverlap) {
    // An L shape of area 3.
    const std::vector<glm::dvec3> l{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    const auto tris = triangulate_polygon(l);
    ASSERT_EQ(tris.size(), 4u);
    EXPECT_NEAR(triangles_area(l, tris), 3.0, 1e-12);
    for (const auto& t : tris) {
        const glm::dvec3 n = newell_normal(std::vector<glm::dvec3>{l[t[0]], l[t[1]], l[t[2]]});
        EXPECT_GT(n.z, 0.0);  // same winding as the polygon
    }
}

TEST(Polygon, NonPlanarQuadSplitsAlongShorterDiagonal) {
    const std::vector<glm::dvec3> q{{0, 0, 0}, {3, 0, 0}, {3, 1, 0.2}, {0, 1, 0}};
    const auto tris = triangulate_polygon(q);
    ASSERT_EQ(tris.size(), 2u);
    // Diagonal 1-3 is shorter than 0-2 (same length in x and y, but 0-2 also climbs in z).
    const bool uses_13 = (tris[0][0] == 1 || tris[0][1] == 1 || tris[0][2] == 1) &&
                         (tris[1][0] == 1 || tris[1][1] == 1 || tris[1][2] == 1);
    EXPECT_TRUE(uses_13);
}

}  // namespace
}  // namespace rad
