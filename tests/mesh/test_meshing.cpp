// Patch meshing: area is preserved, no edge exceeds the patch size, the mesh conforms (no T-vertices), and
// the counts are the ones worked out by hand.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <map>
#include <set>

#include "rad/geometry/polygon.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/util/error.hpp"

namespace rad {
namespace {

double patch_area_sum(const PatchMesh& mesh, std::uint32_t surface) {
    double sum = 0.0;
    for (auto p = mesh.surface_begin[surface]; p < mesh.surface_begin[surface + 1]; ++p)
        sum += mesh.patches[p].area;
    return sum;
}

double longest_edge(const PatchMesh& mesh, std::size_t patch) {
    double longest = 0.0;
    const int n = mesh.corner_count(patch);
    for (int k = 0; k < n; ++k) {
        const glm::dvec3 a = mesh.points[mesh.corners[patch][k]];
        const glm::dvec3 b = mesh.points[mesh.corners[patch][(k + 1) % n]];
        longest = std::max(longest, glm::length(b - a));
    }
    return longest;
}

// A T-vertex: a corner of the same surface lying strictly inside a patch edge.
std::size_t count_t_vertices(const PatchMesh& mesh) {
    std::size_t found = 0;
    for (std::size_t s = 0; s + 1 < mesh.surface_begin.size(); ++s) {
        std::set<std::uint32_t> corners;
        for (auto p = mesh.surface_begin[s]; p < mesh.surface_begin[s + 1]; ++p) {
            for (int k = 0; k < mesh.corner_count(p); ++k) corners.insert(mesh.corners[p][k]);
        }
        for (auto p = mesh.surface_begin[s]; p < mesh.surface_begin[s + 1]; ++p) {
            const int n = mesh.corner_count(p);
            for (int k = 0; k < n; ++k) {
                const glm::dvec3 a = mesh.points[mesh.corners[p][k]];
                const glm::dvec3 b = mesh.points[mesh.corners[p][(k + 1) % n]];
                const double len = glm::length(b - a);
                for (std::uint32_t c : corners) {
                    const glm::dvec3 q = mesh.points[c];
                    const double t = glm::dot(q - a, b - a) / (len * len);
                    const double off = glm::length(a + t * (b - a) - q);
                    if (t > 1e-9 && t < 1 - 1e-9 && off < 1e-9 * len) ++found;
                }
            }
        }
    }
    return found;
}

void expect_well_meshed(const Scene& scene, double patch_size) {
    const PatchMesh mesh = build_patches(scene, {patch_size});
    ASSERT_EQ(mesh.surface_begin.size(), scene.surfaces.size() + 1);
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        const double expected = surface_area(scene.surfaces[s].mesh);
        EXPECT_NEAR(patch_area_sum(mesh, s), expected, 1e-9 * expected) << scene.surfaces[s].name;
    }
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        EXPECT_LE(longest_edge(mesh, p), patch_size * (1 + 1e-12));
        EXPECT_GT(mesh.patches[p].area, 0.0);
        // The stored normal agrees with the corners' winding.
        std::vector<glm::dvec3> poly;
        for (int k = 0; k < mesh.corner_count(p); ++k) poly.push_back(mesh.points[mesh.corners[p][k]]);
        EXPECT_GT(glm::dot(newell_normal(poly), mesh.patches[p].normal), 0.0);
    }
    EXPECT_EQ(count_t_vertices(mesh), 0u);
    EXPECT_EQ(count_patches(scene, patch_size), mesh.size());
    ASSERT_EQ(mesh.positions.size(), mesh.points.size());
}

TEST(Meshing, CornellBoxPreservesAreaBoundsEdgesAndConforms) {
    const Scene scene = make_cornell_box();
    for (double size : {200.0, 100.0, 37.0}) expect_well_meshed(scene, size);
}

TEST(Meshing, CornellBoxPatchCountAtSize100) {
    // Worked out by hand, edges cut into ceil(length / 100) segments, unified across shared edges:
    // floor 6x6, back wall 6x6, right wall 6x6, light 2x2, ceiling (3+2+3)^2 - 2x2 = 60, short block 5 faces
    // of 2x2, tall block top 2x2 and 4 sides 2x4, and the non-planar left wall as two triangles whose
    // 783.5-long diagonal needs 8 segments: 2 x 8^2.
    const PatchMesh mesh = build_patches(make_cornell_box(), {100.0});
    EXPECT_EQ(mesh.size(), 36u + 60u + 4u + 36u + 36u + 128u + 20u + 36u);
}

TEST(Meshing, QuadsStayQuads) {
    const Scene cube = make_cube();
    const PatchMesh mesh = build_patches(cube, {0.25});
    EXPECT_EQ(mesh.size(), 6u * 16u);
    for (std::size_t p = 0; p < mesh.size(); ++p) EXPECT_FALSE(mesh.is_triangle(p));
}

Scene soup_scene(std::vector<glm::dvec3> positions, std::vector<std::vector<std::uint32_t>> polygons) {
    PolygonSoup soup;
    soup.source = "test";
    soup.positions = std::move(positions);
    soup.groups.push_back({"s", Material{"m", glm::dvec3(0.5), glm::dvec3(1.0)}});
    for (auto& p : polygons) soup.polygons.push_back({std::move(p), 0});
    return build_scene(soup);
}

TEST(Meshing, TriangleIsCutIntoNSquaredTriangles) {
    const Scene scene = soup_scene({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    // The hypotenuse (1.414) needs 3 segments of at most 0.5, so all three edges get 3: 9 triangles.
    const PatchMesh mesh = build_patches(scene, {0.5});
    EXPECT_EQ(mesh.size(), 9u);
    expect_well_meshed(scene, 0.5);
}

TEST(Meshing, MixedQuadsAndTrianglesConform) {
    // A long quad beside a triangle sharing its right edge, and a convex pentagon fanned around its centre.
    const Scene scene = soup_scene(
        {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {0, 1, 0}, {4, 0.5, 0}, {0, 2, 0}, {1.5, 2.6, 0}, {3, 2, 0}},
        {{0, 1, 2, 3}, {1, 4, 2}, {3, 2, 7, 6, 5}});
    for (double size : {1.0, 0.3, 0.17}) expect_well_meshed(scene, size);
}

TEST(Meshing, TooManyPatchesNamesTheOptionAndASizeThatFits) {
    MeshingOptions options;
    options.patch_size = 0.001;
    options.max_patches = 1000;
    try {
        build_patches(make_cube(), options);
        FAIL() << "expected an InputError";
    } catch (const SettingError& e) {
        EXPECT_EQ(e.setting(), "patch_size");
        const std::string what = e.what();
        // The suggested size must actually fit.
        const double suggested = std::stod(what.substr(what.rfind("use patch size ") + 15));
        EXPECT_LE(count_patches(make_cube(), suggested), 1000u) << what;
    }
}

TEST(Meshing, DefaultPatchSizeScalesWithTheScene) {
    EXPECT_DOUBLE_EQ(default_patch_size(make_cube()), 1.0 / 16.0);
    EXPECT_DOUBLE_EQ(default_patch_size(make_cornell_box()), 559.2 / 16.0);
}

}  // namespace
}  // namespace rad
