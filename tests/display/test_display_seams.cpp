// Seams where surfaces meet: a corner of one surface inside an edge of another is a T-vertex the patches'
// outlines do not list (surfaces share no corners). The display mesh puts a vertex of the other surface's
// triangles there, so no crack opens, and the colours stay what the edge showed.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "rad/display/display_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/polygon_soup.hpp"

namespace rad {
namespace {

// A 1 x 1 floor (y = 0) and a wall 0.5 wide standing on its edge z = 0, from x = 0 to 0.5: the wall's
// corner (0.5, 0, 0) lies inside the floor's edge. One patch each.
PatchMesh floor_and_short_wall() {
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {0, 0, 1},   {1, 0, 1},   {1, 0, 0},
                      {0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}};
    soup.groups = {{"floor", default_material()}, {"wall", default_material()}};
    soup.polygons = {{{0, 1, 2, 3}, 0}, {{4, 5, 6, 7}, 1}};
    return build_patches(build_scene(soup), MeshingOptions{.patch_size = 1.0});
}

// Whether a corner of some triangle lies strictly inside an edge of another (within 1e-6), the pattern that
// leaves crack pixels.
bool has_t_junction(const DisplayMesh& d) {
    for (const glm::uvec3& t : d.triangles) {
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 a(d.positions[t[k]]), b(d.positions[t[(k + 1) % 3]]);
            for (const glm::vec3& q : d.positions) {
                const glm::dvec3 p(q);
                const double s = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
                if (s <= 1e-6 || s >= 1.0 - 1e-6) continue;
                if (glm::length(p - (a + s * (b - a))) < 1e-6) return true;
            }
        }
    }
    return false;
}

double area_of_surface_triangles(const DisplayMesh& d, const PatchMesh& patches, std::uint32_t surface) {
    double area = 0.0;
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        if (patches.patches[d.triangle_patch[t]].surface != surface) continue;
        const glm::dvec3 a(d.positions[d.triangles[t][0]]), b(d.positions[d.triangles[t][1]]),
            c(d.positions[d.triangles[t][2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

TEST(DisplaySeams, ACornerInsideAnotherSurfacesEdgeBecomesAVertexOfItsTriangles) {
    const PatchMesh patches = floor_and_short_wall();
    ASSERT_EQ(patches.size(), 2u);
    for (ColourMode mode : {ColourMode::smooth, ColourMode::flat}) {
        const DisplayMesh d = build_display_mesh(patches, DisplayOptions{.mode = mode});
        EXPECT_FALSE(has_t_junction(d));
        EXPECT_NEAR(area_of_surface_triangles(d, patches, 0), 1.0, 1e-9);
        EXPECT_NEAR(area_of_surface_triangles(d, patches, 1), 0.5, 1e-9);
        // The floor's vertex at the wall's corner shows what the floor's edge showed there: with a radiosity
        // that differs between the two patches, the floor's own.
        const std::vector<glm::vec3> shown =
            vertex_radiance(d, std::vector<glm::dvec3>{{3.0, 3.0, 3.0}, {7.0, 7.0, 7.0}});
        bool found = false;
        for (std::size_t t = 0; t < d.triangles.size(); ++t) {
            if (d.triangle_patch[t] != 0) continue;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = d.triangles[t][k];
                if (glm::length(glm::dvec3(d.positions[v]) - glm::dvec3(0.5, 0.0, 0.0)) > 1e-6) continue;
                found = true;
                EXPECT_NEAR(shown[v].x, 3.0 / std::numbers::pi, 1e-6);
            }
        }
        EXPECT_TRUE(found);
    }
}

TEST(DisplaySeams, SurfacesMeetingAtMatchingCornersGetNothingAdded) {
    // The cube's faces meet at corners on the same grid: nothing to close, and no triangle added.
    const PatchMesh patches = build_patches(make_builtin_scene("cube"), MeshingOptions{.patch_size = 0.25});
    const DisplayMesh d = build_display_mesh(patches);
    EXPECT_FALSE(has_t_junction(d));
    EXPECT_EQ(d.triangles.size(), 2 * patches.size());
}

}  // namespace
}  // namespace rad
