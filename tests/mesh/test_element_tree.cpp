// The element tree behind adaptive and hierarchical meshes: splitting keeps area, children share midpoints
// with their neighbours, and the leaf mesh lists every T-vertex on the edges of the larger leaves.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <set>

#include "rad/mesh/element_tree.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"

namespace rad {
namespace {

PatchMesh cornell_patches(double patch_size) {
    return build_patches(make_builtin_scene("cornell"), MeshingOptions{patch_size});
}

double total_area(const PatchMesh& mesh) {
    double sum = 0.0;
    for (const Patch& p : mesh.patches) sum += p.area;
    return sum;
}

// Is p strictly inside the segment a-b?
bool inside_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = glm::dot(p - a, ab) / glm::dot(ab, ab);
    return t > 1e-9 && t < 1.0 - 1e-9 && glm::length(a + t * ab - p) < 1e-9 * glm::length(ab);
}

TEST(ElementTree, SplittingQuadsAndTrianglesKeepsAreaCentroidAndNormal) {
    const PatchMesh base = cornell_patches(0.0);
    ElementTree tree(base);
    for (std::uint32_t e = 0; e < base.size(); e += 7) {
        const std::uint32_t first = tree.split(e);
        double area = 0.0;
        glm::dvec3 moment(0.0);
        for (std::uint32_t c = first; c < first + 4; ++c) {
            EXPECT_EQ(tree[c].parent, e);
            EXPECT_EQ(tree[c].level, 1u);
            EXPECT_EQ(tree[c].shape.surface, base.patches[e].surface);
            // A quarter exactly for parallelograms; the Cornell box's quads are slightly skewed.
            EXPECT_NEAR(tree[c].shape.area, base.patches[e].area / 4.0, 1e-2 * base.patches[e].area);
            area += tree[c].shape.area;
            moment += tree[c].shape.area * tree[c].shape.centroid;
        }
        EXPECT_NEAR(area, base.patches[e].area, 1e-12 * area);
        EXPECT_LT(glm::length(moment / area - base.patches[e].centroid), 1e-9);
        EXPECT_EQ(tree.split(e), first) << "splitting twice returns the same children";
    }
    const std::vector<std::uint32_t> leaves = tree.leaves();
    EXPECT_EQ(leaves.size(), tree.leaf_count());
    EXPECT_NEAR(total_area(tree.leaf_mesh(leaves)), total_area(base), 1e-9 * total_area(base));
}

TEST(ElementTree, AnUnsplitTreeGivesTheBaseMeshWithoutOutlines) {
    const PatchMesh base = cornell_patches(0.0);
    const ElementTree tree(base);
    const PatchMesh leaves = tree.leaf_mesh(tree.leaves());
    ASSERT_EQ(leaves.size(), base.size());
    EXPECT_EQ(leaves.corners, base.corners);
    EXPECT_EQ(leaves.surface_begin, base.surface_begin);
    EXPECT_TRUE(leaves.outline.empty());
}

// Split one patch twice over: its neighbours on the same surface get T-vertices on the shared edges, and
// every corner of the same surface that lies inside a leaf's edge is in that leaf's outline, in order.
TEST(ElementTree, OutlinesHoldEveryTVertexInOrder) {
    const PatchMesh base = cornell_patches(0.0);
    ElementTree tree(base);
    // A patch in the middle of the first surface, and one child of it again.
    const std::uint32_t middle = (base.surface_begin[0] + base.surface_begin[1]) / 2;
    const std::uint32_t first = tree.split(middle);
    tree.split(first + 2);
    const std::vector<std::uint32_t> leaves = tree.leaves();
    const PatchMesh mesh = tree.leaf_mesh(leaves);
    ASSERT_FALSE(mesh.outline.empty());
    std::size_t t_vertices = 0;
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        const std::uint32_t s = mesh.patches[q].surface;
        std::set<std::uint32_t> surface_points;
        for (std::uint32_t r = mesh.surface_begin[s]; r < mesh.surface_begin[s + 1]; ++r)
            for (int k = 0; k < mesh.corner_count(r); ++k) surface_points.insert(mesh.corners[r][k]);
        const std::span<const std::uint32_t> outline(mesh.outline.data() + mesh.outline_begin[q],
                                                     mesh.outline_begin[q + 1] - mesh.outline_begin[q]);
        const int n = mesh.corner_count(q);
        // The outline's points, walked in order, advance monotonically along each edge.
        std::size_t at = 0;
        for (int k = 0; k < n; ++k) {
            const glm::dvec3 a = mesh.points[mesh.corners[q][k]],
                             b = mesh.points[mesh.corners[q][(k + 1) % n]];
            ASSERT_EQ(outline[at], mesh.corners[q][k]);
            ++at;
            double last = 0.0;
            std::size_t on_edge = 0;
            while (at < outline.size() && outline[at] != mesh.corners[q][(k + 1) % n]) {
                const glm::dvec3 p = mesh.points[outline[at]];
                ASSERT_TRUE(inside_segment(p, a, b));
                const double t = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
                EXPECT_GT(t, last);
                last = t;
                ++on_edge, ++at;
            }
            std::size_t expected = 0;
            for (std::uint32_t p : surface_points) expected += inside_segment(mesh.points[p], a, b) ? 1 : 0;
            EXPECT_EQ(on_edge, expected) << "patch " << q << " edge " << k;
            t_vertices += on_edge;
        }
        EXPECT_EQ(at, outline.size());
    }
    // Four neighbours get one T-vertex each from the first split; the second split adds two on the first
    // split's children's edges and one or two on the neighbours' (at least four more in all).
    EXPECT_GE(t_vertices, 8u);
}

}  // namespace
}  // namespace rad
