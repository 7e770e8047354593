// Linear reconstruction meets patches whose neighbours lie nearly in a line (small elements beside large
// ones, the slivers of real models), where the least-squares gradient is huge: a vertex keeps within the
// range of the patches it is made from, widened by that range, so it shows no bright or dark artifact.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "rad/display/display_mesh.hpp"
#include "rad/scene/polygon_soup.hpp"

namespace rad {
namespace {

// Three quads in a row, the last a trapezoid whose far edge is 4 % longer: the middle quad's neighbours'
// centroids lie 0.01 off a line, so its gradient across the row is about 100 times its step along it.
PatchMesh nearly_straight_row() {
    PolygonSoup soup;
    soup.source = "row";
    soup.groups.push_back({"row", default_material()});
    soup.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 0, 1},
                      {2, 0, 0}, {2, 0, 1}, {3, 0, 0}, {3, 0, 1.04}};
    soup.polygons = {{{0, 1, 3, 2}, 0}, {{2, 3, 5, 4}, 0}, {{4, 5, 7, 6}, 0}};
    return build_patches(build_scene(soup), MeshingOptions{.patch_size = 10.0});
}

TEST(DisplayOvershoot, AVertexStaysNearTheRangeOfItsPatches) {
    const PatchMesh mesh = nearly_straight_row();
    ASSERT_EQ(mesh.size(), 3u);
    const DisplayMesh display = build_display_mesh(mesh);
    // Radiosity 1, 0.5, 1 along the row (the patches in the order of their centroids' x).
    std::vector<glm::dvec3> radiosity(3);
    for (std::size_t p = 0; p < 3; ++p)
        radiosity[p] =
            glm::dvec3(mesh.patches[p].centroid.x > 1.0 && mesh.patches[p].centroid.x < 2.0 ? 0.5 : 1.0);
    const std::vector<glm::vec3> radiance = vertex_radiance(display, radiosity);
    float lowest = 1e30f, highest = 0.0f;
    for (const glm::vec3& l : radiance) {
        lowest = std::min(lowest, l.x);
        highest = std::max(highest, l.x);
    }
    // Within [0.5 − 0.5, 1 + 0.5], over π; unlimited, a corner of the middle quad showed 25.8.
    EXPECT_LE(highest * std::numbers::pi, 1.5 + 1e-5);
    EXPECT_GE(lowest, 0.0f);
    EXPECT_GT(highest * std::numbers::pi, 1.0);  // the linear reconstruction still extrapolates
}

}  // namespace
}  // namespace rad
