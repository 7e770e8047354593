// Display meshes and per-vertex radiance: no colour bleeds across surfaces or creases, weights are area
// weights, smooth mode reproduces a linear field at interior vertices, flat mode shows each patch as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "rad/display/display_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/polygon_soup.hpp"

namespace rad {
namespace {

constexpr double kPi = std::numbers::pi;

PatchMesh mesh_of(const Scene& scene, double patch_size) {
    return build_patches(scene, MeshingOptions{.patch_size = patch_size});
}

double triangle_area(const DisplayMesh& d, std::size_t t) {
    const glm::dvec3 a(d.positions[d.triangles[t].x]), b(d.positions[d.triangles[t].y]),
        c(d.positions[d.triangles[t].z]);
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

glm::dvec3 triangle_normal(const DisplayMesh& d, std::size_t t) {
    const glm::dvec3 a(d.positions[d.triangles[t].x]), b(d.positions[d.triangles[t].y]),
        c(d.positions[d.triangles[t].z]);
    return glm::normalize(glm::cross(b - a, c - a));
}

// Both modes cover each patch exactly, keep its winding, and give every vertex weights summing to 1.
void expect_well_formed(const DisplayMesh& d, const PatchMesh& mesh) {
    ASSERT_EQ(d.normals.size(), d.vertex_count());
    ASSERT_EQ(d.weight_begin.size(), d.vertex_count() + 1);
    ASSERT_EQ(d.triangle_patch.size(), d.triangles.size());
    EXPECT_EQ(d.patch_count, mesh.size());
    std::vector<double> covered(mesh.size(), 0.0);
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const std::uint32_t p = d.triangle_patch[t];
        covered[p] += triangle_area(d, t);
        EXPECT_GT(glm::dot(triangle_normal(d, t), mesh.patches[p].normal), 0.999) << "triangle " << t;
    }
    for (std::size_t p = 0; p < mesh.size(); ++p)
        EXPECT_NEAR(covered[p], mesh.patches[p].area, 1e-5 * mesh.patches[p].area);
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        double sum = 0.0;
        for (auto k = d.weight_begin[v]; k < d.weight_begin[v + 1]; ++k) sum += d.weight[k];
        EXPECT_NEAR(sum, 1.0, 1e-6) << "vertex " << v;
        EXPECT_NEAR(glm::length(d.normals[v]), 1.0f, 1e-5f);
    }
}

TEST(DisplayMesh, CubeCountsInBothModes) {
    const PatchMesh mesh = mesh_of(make_cube(), 0.5);  // 2 x 2 patches on each of 6 faces
    const DisplayMesh smooth = build_display_mesh(mesh);
    expect_well_formed(smooth, mesh);
    EXPECT_EQ(smooth.vertex_count(), 6u * 9u);  // a 3 x 3 grid of corners per face, none shared across faces
    EXPECT_EQ(smooth.triangles.size(), 6u * 4u * 2u);
    const DisplayMesh flat = build_display_mesh(mesh, {.mode = ColourMode::flat});
    expect_well_formed(flat, mesh);
    EXPECT_EQ(flat.vertex_count(), 6u * 4u * 4u);
    EXPECT_EQ(flat.triangles.size(), 6u * 4u * 2u);
}

// Each Cornell surface gets its own constant radiosity: every vertex must show exactly its surface's value,
// and no vertex may draw on patches of two surfaces or on faces bent by more than the crease angle (the
// blocks are single surfaces with five faces each).
TEST(DisplayMesh, CornellWallsDoNotBleed) {
    const PatchMesh mesh = mesh_of(make_cornell_box(), 60.0);
    const DisplayMesh d = build_display_mesh(mesh);
    expect_well_formed(d, mesh);
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t p = 0; p < mesh.size(); ++p) {
        const double s = mesh.patches[p].surface;
        b[p] = glm::dvec3(1.0 + s, 10.0 * (1.0 + s), 0.5);
    }
    const std::vector<glm::vec3> radiance = vertex_radiance(d, b);
    ASSERT_EQ(radiance.size(), d.vertex_count());
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        const std::uint32_t first = d.weight_patch[d.weight_begin[v]];
        const Patch& reference = mesh.patches[first];
        for (auto k = d.weight_begin[v]; k < d.weight_begin[v + 1]; ++k) {
            const Patch& other = mesh.patches[d.weight_patch[k]];
            ASSERT_EQ(other.surface, reference.surface) << "vertex " << v;
            ASSERT_GT(glm::dot(other.normal, reference.normal), std::cos(30.0 * kPi / 180.0))
                << "vertex " << v;
        }
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(radiance[v][c], b[first][c] / kPi, 1e-6 * b[first][c]) << "vertex " << v;
        }
        // The vertex sits on a corner of each of its patches.
        EXPECT_GT(glm::dot(glm::dvec3(d.normals[v]), reference.normal), 0.999);
    }
}

glm::dvec3 linear_field(const glm::dvec3& x) {
    return glm::dvec3(1.0 + 2.0 * x.x + 3.0 * x.z, 5.0 - x.x, 2.0 + x.z);
}

// With the area-weighted average, an interior vertex of a regular grid is the mean of the four centroids
// around it, so a radiosity linear in position comes back exactly there: L = B(x) / π.
TEST(DisplayMesh, AveragingReproducesALinearFieldInside) {
    const PatchMesh mesh = mesh_of(make_cube(), 0.25);
    DisplayOptions options;
    options.reconstruction = Reconstruction::average;
    const DisplayMesh d = build_display_mesh(mesh, options);
    auto field = linear_field;
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t p = 0; p < mesh.size(); ++p) b[p] = field(mesh.patches[p].centroid);
    const std::vector<glm::vec3> radiance = vertex_radiance(d, b);
    std::size_t interior = 0;
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        if (d.weight_begin[v + 1] - d.weight_begin[v] != 4)
            continue;  // corners and edges of a face see fewer
        ++interior;
        const glm::dvec3 expected = field(glm::dvec3(d.positions[v])) / kPi;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(radiance[v][c], expected[c], 1e-6) << "vertex " << v;
    }
    EXPECT_EQ(interior, 6u * 9u);  // a 3 x 3 block of interior corners on each face
}

// Linear reconstruction (the default) extrapolates each patch along its least-squares gradient, so a linear
// field comes back exactly at every vertex, on the faces' borders and corners too, where averaging takes
// the value half a patch inside.
TEST(DisplayMesh, LinearReconstructionReproducesALinearFieldEverywhere) {
    const PatchMesh mesh = mesh_of(make_cube(), 0.25);
    const DisplayMesh d = build_display_mesh(mesh);
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t p = 0; p < mesh.size(); ++p) b[p] = linear_field(mesh.patches[p].centroid);
    const std::vector<glm::vec3> radiance = vertex_radiance(d, b);
    ASSERT_EQ(d.vertex_count(), 6u * 25u);
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        const glm::dvec3 expected = linear_field(glm::dvec3(d.positions[v])) / kPi;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(radiance[v][c], expected[c], 1e-5) << "vertex " << v;
    }
    // Averaging misses at a face's corner: it shows the one patch's centroid value there.
    DisplayOptions average;
    average.reconstruction = Reconstruction::average;
    const std::vector<glm::vec3> averaged = vertex_radiance(build_display_mesh(mesh, average), b);
    double worst = 0.0;
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        worst = std::max(worst, std::abs(averaged[v].x - linear_field(glm::dvec3(d.positions[v])).x / kPi));
    }
    EXPECT_GT(worst, 0.1);
}

// Beside a step (a shadow edge) extrapolation can undershoot; the radiance shown is never negative.
TEST(DisplayMesh, LinearReconstructionNeverShowsNegativeLight) {
    const PatchMesh mesh = mesh_of(make_cube(), 0.125);
    const DisplayMesh d = build_display_mesh(mesh);
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t p = 0; p < mesh.size(); ++p)
        b[p] = glm::dvec3(mesh.patches[p].centroid.x < 0.5 ? 0.0 : 10.0);
    for (const glm::vec3& l : vertex_radiance(d, b)) EXPECT_GE(l.x, 0.0f);
}

TEST(DisplayMesh, FlatModeShowsEachPatchAsItIs) {
    const PatchMesh mesh = mesh_of(make_cornell_box(), 100.0);
    const DisplayMesh d = build_display_mesh(mesh, {.mode = ColourMode::flat});
    expect_well_formed(d, mesh);
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t p = 0; p < mesh.size(); ++p) b[p] = glm::dvec3(static_cast<double>(p), 1.0, 2.0 * p);
    const std::vector<glm::vec3> radiance = vertex_radiance(d, b);
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const glm::dvec3 expected = b[d.triangle_patch[t]] / kPi;
        for (int k = 0; k < 3; ++k) {
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(radiance[d.triangles[t][k]][c], expected[c], 1e-6 * (1.0 + expected[c]));
        }
    }
}

// One surface of two unit squares meeting along the z axis at a given angle between their normals.
Scene hinge(double angle_degrees) {
    const double a = angle_degrees * kPi / 180.0;
    PolygonSoup soup;
    soup.source = "hinge";
    soup.groups.push_back({"hinge", default_material()});
    // Square 1 in the plane y = 0 (normal +y); square 2 turned about the z axis by `a`.
    soup.positions = {{0, 0, 0},
                      {0, 0, 1},
                      {1, 0, 1},
                      {1, 0, 0},
                      {-std::cos(a), std::sin(a), 0},
                      {-std::cos(a), std::sin(a), 1}};
    soup.polygons.push_back({{0, 1, 2, 3}, 0});
    soup.polygons.push_back({{4, 5, 1, 0}, 0});
    return build_scene(soup);
}

TEST(DisplayMesh, CreaseAngleDecidesWhereVerticesSplit) {
    for (const double angle : {20.0, 60.0}) {
        const PatchMesh mesh = mesh_of(hinge(angle), 2.0);  // one patch per square
        ASSERT_EQ(mesh.size(), 2u);
        ASSERT_NEAR(glm::dot(mesh.patches[0].normal, mesh.patches[1].normal), std::cos(angle * kPi / 180.0),
                    1e-9);
        const DisplayMesh d = build_display_mesh(mesh);
        expect_well_formed(d, mesh);
        EXPECT_EQ(d.vertex_count(), angle < 30.0 ? 6u : 8u) << angle << "°";
        const DisplayMesh sharp = build_display_mesh(mesh, {.crease_angle_degrees = 10.0});
        EXPECT_EQ(sharp.vertex_count(), 8u);
        // Shared hinge vertices take the mean of both squares (equal areas) and bisect their normals.
        const std::vector<glm::vec3> radiance =
            vertex_radiance(d, std::vector<glm::dvec3>{glm::dvec3(1.0), glm::dvec3(3.0)});
        std::size_t shared = 0;
        for (std::size_t v = 0; v < d.vertex_count(); ++v) {
            if (d.weight_begin[v + 1] - d.weight_begin[v] == 2) {
                ++shared;
                EXPECT_NEAR(radiance[v].x, 2.0 / kPi, 1e-6);
                const double half = std::cos(0.5 * angle * kPi / 180.0);
                EXPECT_NEAR(glm::dot(glm::dvec3(d.normals[v]), mesh.patches[0].normal), half, 1e-6);
            } else {
                EXPECT_NEAR(radiance[v].x, d.weight_patch[d.weight_begin[v]] == 0 ? 1.0 / kPi : 3.0 / kPi,
                            1e-6);
            }
        }
        EXPECT_EQ(shared, angle < 30.0 ? 2u : 0u);
    }
}

TEST(DisplayMesh, WrongSizesAreRefused) {
    const PatchMesh mesh = mesh_of(make_cube(), 1.0);
    const DisplayMesh d = build_display_mesh(mesh);
    std::vector<glm::vec3> out(d.vertex_count() + 1);
    EXPECT_THROW(vertex_radiance(d, std::vector<glm::dvec3>(mesh.size()), out), std::invalid_argument);
    EXPECT_THROW(vertex_radiance(d, std::vector<glm::dvec3>(mesh.size() - 1)), std::invalid_argument);
    EXPECT_THROW(build_display_mesh(mesh, {.crease_angle_degrees = -1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace rad
