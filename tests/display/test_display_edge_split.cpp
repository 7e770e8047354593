// Splitting a display mesh's interior edges at their midpoints (split_display_edges), as the direct light
// does along shadow edges: the mesh stays conforming (no T-junction, so no crack), each patch keeps its area
// and its triangles' orientation, and a new vertex shows what the triangles showed there before the split.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <stdexcept>
#include <utility>

#include "display/display_edge_split.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"

namespace rad {
namespace {

// The Cornell box's display at its default patches (smooth reconstruction: vertices weigh several patches).
DisplayMesh cornell_display() {
    const Scene scene = make_builtin_scene("cornell");
    return build_display_mesh(build_patches(scene, MeshingOptions{}));
}

std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const DisplayMesh& d) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const glm::uvec3& t : d.triangles)
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
    return uses;
}

std::vector<double> patch_areas(const DisplayMesh& d) {
    std::vector<double> area(d.patch_count, 0.0);
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const glm::dvec3 a(d.positions[d.triangles[t][0]]), b(d.positions[d.triangles[t][1]]),
            c(d.positions[d.triangles[t][2]]);
        area[d.triangle_patch[t]] += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

// The area-weighted normal of each patch's triangles: a flipped piece would turn it.
std::vector<glm::dvec3> patch_orientations(const DisplayMesh& d) {
    std::vector<glm::dvec3> normal(d.patch_count, glm::dvec3(0.0));
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const glm::dvec3 a(d.positions[d.triangles[t][0]]), b(d.positions[d.triangles[t][1]]),
            c(d.positions[d.triangles[t][2]]);
        normal[d.triangle_patch[t]] += glm::cross(b - a, c - a);
    }
    return normal;
}

// Every third interior edge, so triangles are split one, two and three ways.
std::vector<DisplayEdge> some_edges(const DisplayMesh& d) {
    std::vector<DisplayEdge> edges;
    const std::vector<DisplayEdge> interior = interior_edges(d);
    for (std::size_t k = 0; k < interior.size(); k += 3) edges.push_back(interior[k]);
    return edges;
}

TEST(DisplayEdgeSplit, InteriorEdgesAreThoseOfTwoTriangles) {
    const DisplayMesh d = cornell_display();
    const auto uses = edge_uses(d);
    const std::vector<DisplayEdge> interior = interior_edges(d);
    std::size_t shared = 0;
    for (const auto& [edge, count] : uses) shared += count == 2;
    EXPECT_EQ(interior.size(), shared);
    for (const DisplayEdge& e : interior) {
        EXPECT_LT(e.a, e.b);
        EXPECT_EQ(uses.at({e.a, e.b}), 2);
    }
    // The box's walls meet at creases and its blocks stand on the floor: some edges are borders.
    EXPECT_LT(shared, uses.size());
}

TEST(DisplayEdgeSplit, KeepsTheMeshConformingAndEachPatchItsAreaAndSide) {
    DisplayMesh d = cornell_display();
    const auto uses_before = edge_uses(d);
    const std::vector<double> area_before = patch_areas(d);
    const std::vector<glm::dvec3> side_before = patch_orientations(d);
    const std::size_t vertices = d.vertex_count(), triangles = d.triangles.size();
    const std::vector<DisplayEdge> edges = some_edges(d);
    ASSERT_GT(edges.size(), 100u);

    EXPECT_EQ(split_display_edges(d, edges), vertices);
    EXPECT_EQ(d.vertex_count(), vertices + edges.size());
    EXPECT_EQ(d.triangles.size(),
              triangles + 2 * edges.size());  // each split edge adds a piece to both sides
    EXPECT_EQ(d.triangle_patch.size(), d.triangles.size());
    EXPECT_EQ(d.normals.size(), d.vertex_count());
    EXPECT_EQ(d.weight_begin.size(), d.vertex_count() + 1);

    // Conforming: an edge is on as many triangles as before (2 inside, 1 on a border), none on one alone that
    // was not a border, so no new vertex lies on another triangle's edge.
    std::size_t borders_before = 0, borders_after = 0;
    for (const auto& [edge, count] : uses_before) borders_before += count == 1;
    for (const auto& [edge, count] : edge_uses(d)) {
        EXPECT_LE(count, 2);
        borders_after += count == 1;
    }
    EXPECT_EQ(borders_after, borders_before);

    const std::vector<double> area_after = patch_areas(d);
    const std::vector<glm::dvec3> side_after = patch_orientations(d);
    // Within the rounding of float midpoints at the box's coordinates (~500 mm, float ε ≈ 6e-8 relative).
    for (std::size_t q = 0; q < d.patch_count; ++q) {
        EXPECT_NEAR(area_after[q], area_before[q], 1e-5 * area_before[q]) << "patch " << q;
        EXPECT_NEAR(glm::length(side_after[q] - side_before[q]), 0.0, 1e-5 * glm::length(side_before[q]))
            << "patch " << q;
    }
}

TEST(DisplayEdgeSplit, ANewVertexShowsWhatItsEdgeShowedThere) {
    const PatchMesh patches = build_patches(make_builtin_scene("cornell"), MeshingOptions{});
    DisplayMesh d = build_display_mesh(patches);
    const DisplayMesh before = d;
    const std::vector<DisplayEdge> edges = some_edges(d);
    const std::size_t first = split_display_edges(d, edges);
    // A radiosity linear in the patches' centroids, which the reconstruction keeps within its bounds; it is
    // linear in B, so the midpoint's radiance is the mean of its ends'.
    std::vector<glm::dvec3> radiosity(d.patch_count);
    for (std::size_t q = 0; q < radiosity.size(); ++q) {
        const glm::dvec3& c = patches.patches[q].centroid;
        radiosity[q] = glm::dvec3(2000.0) + glm::dvec3(c.x, c.y, -c.z) + glm::dvec3(0.5 * c.y, c.z, c.x);
    }
    const std::vector<glm::vec3> ends = vertex_radiance(before, radiosity);
    const std::vector<glm::vec3> split = vertex_radiance(d, radiosity);
    for (std::size_t v = 0; v < before.vertex_count(); ++v) ASSERT_EQ(split[v], ends[v]);
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const std::size_t v = first + k;
        const glm::vec3 expected = 0.5f * (ends[edges[k].a] + ends[edges[k].b]);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(split[v][c], expected[c], 1e-5f * std::abs(expected[c])) << v;
        float weights = 0.0f;
        for (std::uint32_t w = d.weight_begin[v]; w < d.weight_begin[v + 1]; ++w) weights += d.weight[w];
        EXPECT_NEAR(weights, 1.0f, 1e-5f);
        const glm::vec3 mid = 0.5f * (before.positions[edges[k].a] + before.positions[edges[k].b]);
        EXPECT_EQ(d.positions[v], mid);
        EXPECT_NEAR(glm::length(d.normals[v]), 1.0f, 1e-5f);
    }
}

TEST(DisplayEdgeSplit, RefusesAMeshWhoseVertexLightIsMade) {
    DisplayMesh d = cornell_display();
    d.light.direct.vertex.assign(d.vertex_count(), glm::vec3(0.0f));
    EXPECT_THROW(split_display_edges(d, some_edges(d)), std::invalid_argument);
}

}  // namespace
}  // namespace rad
