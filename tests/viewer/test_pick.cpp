// Picking a surface by clicking: the ray through a pixel, and the nearest front-facing triangle it meets.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

#include "viewer/pick.hpp"

namespace rad {
namespace {

// Two unit squares facing +z, one at z = 0 (triangles 0, 1) and one nearer the eye at z = 1 covering only
// x in [2, 3] (triangles 2, 3).
const std::vector<glm::vec3> kPositions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {2, 0, 1}, {3, 0, 1}, {3, 1, 1}, {2, 1, 1}};
const std::vector<std::uint32_t> kTriangles{0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};

TEST(Pick, TheNearestFrontFacingTriangleUnderTheRay) {
    const PickRay at_first{{0.75, 0.25, 5.0}, {0.0, 0.0, -1.0}};
    EXPECT_EQ(pick_triangle(kPositions, kTriangles, at_first), 0u);
    const PickRay at_second{{0.25, 0.75, 5.0}, {0.0, 0.0, -1.0}};
    EXPECT_EQ(pick_triangle(kPositions, kTriangles, at_second), 1u);
    const PickRay at_near{{2.5, 0.2, 5.0}, {0.0, 0.0, -1.0}};
    EXPECT_EQ(pick_triangle(kPositions, kTriangles, at_near), 2u);
    const PickRay beside{{1.5, 0.5, 5.0}, {0.0, 0.0, -1.0}};
    EXPECT_FALSE(pick_triangle(kPositions, kTriangles, beside));
    const PickRay from_behind{{0.75, 0.25, -5.0}, {0.0, 0.0, 1.0}};  // culled, as drawn
    EXPECT_FALSE(pick_triangle(kPositions, kTriangles, from_behind));
}

TEST(Pick, TheRayThroughTheViewsCentreLooksAlongTheCamera) {
    const glm::dmat4 view =
        glm::lookAt(glm::dvec3(0.5, 0.5, 4.0), glm::dvec3(0.5, 0.5, 0.0), glm::dvec3(0, 1, 0));
    const glm::dmat4 projection = glm::perspective(glm::radians(45.0), 1.0, 0.1, 100.0);
    const glm::mat4 view_projection(projection * view);
    const PickRay centre = pick_ray(view_projection, {0.0, 0.0});
    EXPECT_NEAR(centre.direction.z, -1.0, 1e-6);
    EXPECT_NEAR(centre.origin.x, 0.5, 1e-5);
    EXPECT_EQ(pick_triangle(kPositions, kTriangles, centre).has_value(), true);
    // The view's top right corner is up and to the right of the centre.
    const PickRay corner = pick_ray(view_projection, {1.0, 1.0});
    EXPECT_GT(corner.direction.x, 0.0);
    EXPECT_GT(corner.direction.y, 0.0);
}

}  // namespace
}  // namespace rad
