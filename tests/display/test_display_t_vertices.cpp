// Display meshes of element-tree leaves, whose corners can lie inside a larger leaf's edge (T-vertices):
// the larger patch is drawn as a fan through them, so the display has no T-junction (no crack), a linear
// radiosity comes back exactly at every vertex, and a T-vertex is one vertex of the large and small patches.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>
#include <map>
#include <numbers>
#include <utility>

#include "display/patch_gradients.hpp"
#include "mesh/patch_boundary.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/mesh/element_tree.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/polygon_soup.hpp"

namespace rad {
namespace {

constexpr double kPi = std::numbers::pi;
const double kCosCrease = std::cos(30.0 * kPi / 180.0);  // the default crease angle

// Do patches q and r meet smoothly (no crease between them)?
bool smooth(const PatchMesh& mesh, std::uint32_t q, std::uint32_t r) {
    return glm::dot(mesh.patches[q].normal, mesh.patches[r].normal) >= kCosCrease;
}

// The leaf of `surface` whose centroid lies nearest `point`.
std::uint32_t leaf_near(const ElementTree& tree, std::uint32_t surface, const glm::dvec3& point) {
    std::uint32_t best = 0;
    double best_distance = INFINITY;
    for (std::uint32_t e : tree.leaves()) {
        const double distance = glm::length(tree[e].shape.centroid - point);
        if (tree[e].shape.surface == surface && distance < best_distance) best = e, best_distance = distance;
    }
    return best;
}

std::uint32_t surface_named(const Scene& scene, const std::string& name) {
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s)
        if (scene.surfaces[s].name == name) return s;
    throw std::invalid_argument("no surface " + name);
}

// The Cornell box's base patches (about 35 mm) with splits that make T-vertices of two levels: on the floor a
// patch, a child of it again, its neighbour and a child of that; a patch of the tall block's side beside
// the crease to its top; a ceiling patch.
PatchMesh split_cornell() {
    const Scene scene = make_builtin_scene("cornell");
    ElementTree tree(build_patches(scene, MeshingOptions{}));
    const std::uint32_t floor = surface_named(scene, "floor");
    const auto split_near = [&](std::uint32_t surface, const glm::dvec3& point) {
        tree.split(leaf_near(tree, surface, point));
    };
    split_near(floor, {278, 0, 280});
    split_near(floor, {286, 0, 288});  // a quarter of the first
    split_near(floor, {313, 0, 280});  // the next patch along x
    split_near(floor, {305, 0, 272});  // its quarter beside the first patch
    split_near(surface_named(scene, "tall block"), {447, 320, 326});
    split_near(surface_named(scene, "ceiling"), {100, 548.8, 100});
    return tree.leaf_mesh(tree.leaves());
}

// A triangle cut into triangular patches, one split, a quarter of it split again and another split: the fan
// works on triangles too.
PatchMesh split_triangle() {
    PolygonSoup soup;
    soup.source = "triangle";
    soup.groups.push_back({"triangle", default_material()});
    soup.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}};
    soup.polygons.push_back({{0, 1, 2}, 0});
    ElementTree tree(build_patches(build_scene(soup), MeshingOptions{.patch_size = 0.25}));
    tree.split(leaf_near(tree, 0, {0.3, 0, 0.3}));
    tree.split(leaf_near(tree, 0, {0.32, 0, 0.32}));
    tree.split(leaf_near(tree, 0, {0.1, 0, 0.5}));
    return tree.leaf_mesh(tree.leaves());
}

std::size_t t_vertex_count(const PatchMesh& mesh) {
    std::size_t count = 0;
    for (std::size_t q = 0; q < mesh.size(); ++q)
        count += patch_boundary(mesh, q).size() - mesh.corner_count(q);
    return count;
}

glm::dvec3 position(const DisplayMesh& d, std::uint32_t v) {
    return glm::dvec3(d.positions[v]);
}

// Is p strictly inside the segment a-b? (Positions are floats, hence the tolerance.)
bool inside_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = glm::dot(p - a, ab) / glm::dot(ab, ab);
    return t > 1e-4 && t < 1.0 - 1e-4 && glm::length(a + t * ab - p) < 1e-4 * glm::length(ab);
}

// What makes a crack: a vertex of a surface strictly inside an edge of one of the surface's triangles.
std::size_t t_junctions(const DisplayMesh& d, const PatchMesh& mesh) {
    std::size_t found = 0;
    for (std::uint32_t s = 0; s + 1 < mesh.surface_begin.size(); ++s) {
        std::vector<std::size_t> triangles;
        std::vector<std::uint32_t> vertices;
        for (std::size_t t = 0; t < d.triangles.size(); ++t) {
            if (mesh.patches[d.triangle_patch[t]].surface != s) continue;
            triangles.push_back(t);
            for (int k = 0; k < 3; ++k) vertices.push_back(d.triangles[t][k]);
        }
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        for (std::size_t t : triangles) {
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 a = position(d, d.triangles[t][k]),
                                 b = position(d, d.triangles[t][(k + 1) % 3]);
                for (std::uint32_t v : vertices) found += inside_segment(position(d, v), a, b) ? 1 : 0;
            }
        }
    }
    return found;
}

struct EdgeUse {
    int forward = 0, backward = 0;  // triangles with the edge low -> high and high -> low
};

// Per surface, the total length of the display edges that only one triangle has: the surface's border
// (and its creases, once per side). A crack adds the edges on both of its sides.
std::vector<double> border_lengths(const DisplayMesh& d, const PatchMesh& mesh) {
    using Edges = std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse>;  // (low, high) vertex
    std::vector<Edges> edges(mesh.surface_begin.size() - 1);
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        auto& uses = edges[mesh.patches[d.triangle_patch[t]].surface];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = d.triangles[t][k], b = d.triangles[t][(k + 1) % 3];
            EdgeUse& use = uses[{std::min(a, b), std::max(a, b)}];
            ++(a < b ? use.forward : use.backward);
        }
    }
    std::vector<double> lengths;
    for (const auto& uses : edges) {
        double length = 0.0;
        for (const auto& [edge, use] : uses) {
            // An edge inside a surface joins two triangles that run along it in opposite directions.
            EXPECT_LE(use.forward, 1);
            EXPECT_LE(use.backward, 1);
            if (use.forward + use.backward == 1)
                length += glm::length(position(d, edge.first) - position(d, edge.second));
        }
        lengths.push_back(length);
    }
    return lengths;
}

// The patch's triangles cover it exactly with its winding, and every vertex's weights sum to 1.
void expect_well_formed(const DisplayMesh& d, const PatchMesh& mesh) {
    ASSERT_EQ(d.normals.size(), d.vertex_count());
    ASSERT_EQ(d.weight_begin.size(), d.vertex_count() + 1);
    ASSERT_EQ(d.triangle_patch.size(), d.triangles.size());
    std::vector<double> covered(mesh.size(), 0.0);
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        const glm::dvec3 a = position(d, d.triangles[t].x), b = position(d, d.triangles[t].y),
                         c = position(d, d.triangles[t].z);
        const glm::dvec3 cross = glm::cross(b - a, c - a);
        covered[d.triangle_patch[t]] += 0.5 * glm::length(cross);
        EXPECT_GT(glm::dot(glm::normalize(cross), mesh.patches[d.triangle_patch[t]].normal), 0.999);
    }
    for (std::size_t p = 0; p < mesh.size(); ++p)
        EXPECT_NEAR(covered[p], mesh.patches[p].area, 1e-5 * mesh.patches[p].area) << "patch " << p;
    for (std::size_t v = 0; v < d.vertex_count(); ++v) {
        double sum = 0.0;
        for (auto k = d.weight_begin[v]; k < d.weight_begin[v + 1]; ++k) sum += d.weight[k];
        EXPECT_NEAR(sum, 1.0, 1e-6) << "vertex " << v;
    }
}

TEST(DisplayTVertices, TheSplitMeshesHaveTVertices) {
    const PatchMesh cornell = split_cornell();
    const PatchMesh triangle = split_triangle();
    EXPECT_GE(t_vertex_count(cornell), 10u);
    EXPECT_GE(t_vertex_count(triangle), 4u);
    std::size_t triangle_fans = 0;
    for (std::size_t q = 0; q < triangle.size(); ++q)
        triangle_fans += triangle.is_triangle(q) && patch_boundary(triangle, q).size() > 3 ? 1 : 0;
    EXPECT_GE(triangle_fans, 1u);
    std::cout << "T-vertices: " << t_vertex_count(cornell) << " on " << cornell.size() << " Cornell patches, "
              << t_vertex_count(triangle) << " on " << triangle.size() << " triangle patches\n";
}

// No vertex lies inside another triangle's edge, and splitting leaves every surface's border as long as
// it was: no crack opens anywhere. Drawn from the corners alone (outlines cleared) the seams are found by
// position instead (close_seams), with the same result.
TEST(DisplayTVertices, SmoothDisplayHasNoCracks) {
    const PatchMesh unsplit = build_patches(make_builtin_scene("cornell"), {});
    const std::vector<double> base = border_lengths(build_display_mesh(unsplit), unsplit);
    for (const PatchMesh& mesh : {split_cornell(), split_triangle()}) {
        for (const Reconstruction reconstruction : {Reconstruction::linear, Reconstruction::average}) {
            const DisplayMesh d = build_display_mesh(mesh, {.reconstruction = reconstruction});
            expect_well_formed(d, mesh);
            EXPECT_EQ(t_junctions(d, mesh), 0u);
        }
        PatchMesh corners_only = mesh;
        corners_only.outline_begin.clear();
        corners_only.outline.clear();
        EXPECT_EQ(t_junctions(build_display_mesh(corners_only), mesh), 0u);
    }
    const PatchMesh mesh = split_cornell();
    const std::vector<double> split = border_lengths(build_display_mesh(mesh), mesh);
    ASSERT_EQ(split.size(), base.size());
    for (std::size_t s = 0; s < base.size(); ++s)
        EXPECT_NEAR(split[s], base[s], 1e-5 * base[s]) << "surface " << s;
}

// Radiosity linear in position, sampled at the patches' centroids.
double linear(const glm::dvec3& x) {
    return 1.0 + 0.3 * x.x + 0.2 * x.z + 0.1 * x.y;
}

std::vector<glm::dvec3> linear_radiosity(const PatchMesh& mesh) {
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t q = 0; q < mesh.size(); ++q) b[q] = glm::dvec3(linear(mesh.patches[q].centroid));
    return b;
}

// Do all the patches vertex v draws on face the same way? (The Cornell box's left wall's do not: its
// published corners are not coplanar, so it is cut into triangles that bend a little from one another.)
bool coplanar(const DisplayMesh& d, const PatchMesh& mesh, std::size_t v) {
    const glm::dvec3 normal = mesh.patches[d.weight_patch[d.weight_begin[v]]].normal;
    for (auto k = d.weight_begin[v]; k < d.weight_begin[v + 1]; ++k)
        if (glm::dot(mesh.patches[d.weight_patch[k]].normal, normal) < 1.0 - 1e-12) return false;
    return true;
}

// Linear reconstruction is exact for a linear field at every vertex drawn from coplanar patches: corners,
// T-vertices and the fans' centres (where a patch shows B itself, its centroid's value). Where patches bend
// a little from one another, each one's gradient lies in its own plane, so it is not exact there.
TEST(DisplayTVertices, LinearReconstructionReproducesALinearFieldAtEveryVertex) {
    for (const PatchMesh& mesh : {split_cornell(), split_triangle()}) {
        const DisplayMesh d = build_display_mesh(mesh);
        const std::vector<glm::vec3> radiance = vertex_radiance(d, linear_radiosity(mesh));
        double worst = 0.0;
        std::size_t checked = 0;
        for (std::size_t v = 0; v < d.vertex_count(); ++v) {
            if (!coplanar(d, mesh, v)) continue;
            ++checked;
            const double expected = linear(glm::dvec3(d.positions[v])) / kPi;
            worst = std::max(worst, std::abs(radiance[v].x - expected) / expected);
        }
        EXPECT_LT(worst, 1e-6);
        EXPECT_GT(checked, d.vertex_count() / 2);
        std::cout << checked << " of " << d.vertex_count() << " vertices checked, worst relative error "
                  << worst << "\n";
    }
}

// The display vertex of patch q's fan at point `point`: the vertex of q's triangles at that position.
std::uint32_t fan_vertex(const DisplayMesh& d, const PatchMesh& mesh, std::uint32_t q, std::uint32_t point) {
    for (std::size_t t = 0; t < d.triangles.size(); ++t) {
        if (d.triangle_patch[t] != q) continue;
        for (int k = 0; k < 3; ++k)
            if (d.positions[d.triangles[t][k]] == mesh.positions[point]) return d.triangles[t][k];
    }
    ADD_FAILURE() << "patch " << q << " has no vertex at point " << point;
    return 0;
}

// Every T-vertex on patch q's boundary with the corners on either side of it.
struct TVertex {
    std::uint32_t patch, point, from, to;
};

std::vector<TVertex> t_vertices(const PatchMesh& mesh) {
    std::vector<TVertex> found;
    for (std::uint32_t q = 0; q < mesh.size(); ++q) {
        const std::span<const std::uint32_t> boundary = patch_boundary(mesh, q);
        const glm::uvec4 c = mesh.corners[q];
        const auto is_corner = [&](std::uint32_t p) {
            return p == c[0] || p == c[1] || p == c[2] || p == c[3];
        };
        for (std::size_t k = 0; k < boundary.size(); ++k) {
            if (is_corner(boundary[k])) continue;
            std::size_t before = k, after = k;
            while (!is_corner(boundary[before])) before = (before + boundary.size() - 1) % boundary.size();
            while (!is_corner(boundary[after])) after = (after + 1) % boundary.size();
            found.push_back({q, boundary[k], boundary[before], boundary[after]});
        }
    }
    return found;
}

// With a linear field the T-vertex shows the value between the large patch's corners on either side, as
// its smaller neighbours' triangles interpolate it: the colour is continuous across the edge.
TEST(DisplayTVertices, ATVertexShowsTheValueBetweenTheCornersOfItsEdge) {
    const PatchMesh mesh = split_cornell();
    const DisplayMesh d = build_display_mesh(mesh);
    const std::vector<glm::vec3> radiance = vertex_radiance(d, linear_radiosity(mesh));
    double worst = 0.0;
    for (const TVertex& t : t_vertices(mesh)) {
        const glm::dvec3 a = mesh.points[t.from], b = mesh.points[t.to], p = mesh.points[t.point];
        const double s = glm::dot(p - a, b - a) / glm::dot(b - a, b - a);
        const double ends = (1.0 - s) * radiance[fan_vertex(d, mesh, t.patch, t.from)].x +
                            s * radiance[fan_vertex(d, mesh, t.patch, t.to)].x;
        const double here = radiance[fan_vertex(d, mesh, t.patch, t.point)].x;
        worst = std::max(worst, std::abs(here - ends) / ends);
    }
    EXPECT_LT(worst, 1e-6);
    std::cout << t_vertices(mesh).size() << " T-vertices, worst relative error " << worst << "\n";
}

// With any radiosity, a T-vertex is a single display vertex of the large patch and of the smaller ones
// that have it as a corner; averaging gives it the area-weighted mean of all of them. Across a crease (the
// tall block's side split beside its top) the faces keep apart vertices, but both pass through the point.
TEST(DisplayTVertices, ATVertexIsOneVertexOfTheLargeAndSmallPatches) {
    const PatchMesh mesh = split_cornell();
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t q = 0; q < mesh.size(); ++q)
        b[q] = glm::dvec3(1.0 + std::sin(0.7 * q) * std::sin(0.7 * q));
    const DisplayMesh d = build_display_mesh(mesh, {.reconstruction = Reconstruction::average});
    const std::vector<glm::vec3> radiance = vertex_radiance(d, b);
    const PointPatches at = patches_at_points(mesh);
    std::size_t shared = 0, across_crease = 0;
    for (const TVertex& t : t_vertices(mesh)) {
        const std::uint32_t v = fan_vertex(d, mesh, t.patch, t.point);
        double area = 0.0, sum = 0.0;
        for (std::uint32_t r : at.at(t.point)) {
            if (!smooth(mesh, r, t.patch)) {
                EXPECT_NE(fan_vertex(d, mesh, r, t.point), v);
                ++across_crease;
                continue;
            }
            EXPECT_EQ(fan_vertex(d, mesh, r, t.point), v) << "patch " << r << " at T-vertex " << t.point;
            area += mesh.patches[r].area;
            sum += mesh.patches[r].area * b[r].x;
            ++shared;
        }
        EXPECT_NEAR(radiance[v].x, sum / area / kPi, 1e-6);
    }
    // The large patch and at least one small one at each T-vertex.
    EXPECT_GE(shared, 2 * t_vertices(mesh).size());
    EXPECT_GE(across_crease, 1u);
}

// Patches meeting at a T-vertex are neighbours for the gradients, even where they share no corner: the
// floor's split of a split leaves a quarter of a quarter that touches the unsplit patch beside it only at
// T-vertices.
TEST(DisplayTVertices, PatchesMeetingAtATVertexAreGradientNeighbours) {
    const PatchMesh mesh = split_cornell();
    const PointPatches at = patches_at_points(mesh);
    const PatchGradients gradients = patch_gradients(mesh, at, kCosCrease);
    const auto neighbours = [&](std::uint32_t q, std::uint32_t r) {
        const auto first = gradients.neighbour.begin() + gradients.begin[q];
        const auto last = gradients.neighbour.begin() + gradients.begin[q + 1];
        return std::find(first, last, r) != last;
    };
    std::size_t through_t_vertex_only = 0;
    for (const TVertex& t : t_vertices(mesh)) {
        for (std::uint32_t r : at.at(t.point)) {
            if (r == t.patch || !smooth(mesh, r, t.patch)) continue;
            EXPECT_TRUE(neighbours(t.patch, r)) << t.patch << " " << r;
            EXPECT_TRUE(neighbours(r, t.patch)) << r << " " << t.patch;
            const glm::uvec4 c = mesh.corners[r];
            bool shares_corner = false;
            for (int k = 0; k < mesh.corner_count(r); ++k)
                for (int j = 0; j < mesh.corner_count(t.patch); ++j)
                    shares_corner = shares_corner || c[k] == mesh.corners[t.patch][j];
            through_t_vertex_only += shares_corner ? 0 : 1;
        }
    }
    EXPECT_GE(through_t_vertex_only, 1u);
}

// Flat mode ignores outlines: each patch is drawn from its corners in its own colour, and a patch with a
// smaller neighbour's corner inside its edge as a fan through that point too (close_seams), so no crack
// opens there either.
TEST(DisplayTVertices, FlatModeDrawsEachPatchInItsOwnColourWithoutCracks) {
    const PatchMesh mesh = split_cornell();
    const DisplayMesh d = build_display_mesh(mesh, {.mode = ColourMode::flat});
    expect_well_formed(d, mesh);
    EXPECT_EQ(t_junctions(d, mesh), 0u);
    std::size_t corners = 0;
    for (std::size_t q = 0; q < mesh.size(); ++q) corners += mesh.corner_count(q);
    EXPECT_GT(d.vertex_count(), corners);
    std::vector<glm::dvec3> b(mesh.size());
    for (std::size_t q = 0; q < mesh.size(); ++q) b[q] = glm::dvec3(1.0 + static_cast<double>(q));
    const std::vector<glm::vec3> radiance = vertex_radiance(d, b);
    for (std::size_t t = 0; t < d.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(radiance[d.triangles[t][k]].x, b[d.triangle_patch[t]].x / kPi,
                        1e-6 * b[d.triangle_patch[t]].x);
}

// Outlines that list only the corners change nothing: the same display mesh to the bit as without them.
TEST(DisplayTVertices, OutlinesWithoutTVerticesGiveTheSameDisplay) {
    const PatchMesh mesh = build_patches(make_builtin_scene("cornell"), {});
    PatchMesh outlined = mesh;
    outlined.outline_begin.push_back(0);
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        for (int k = 0; k < mesh.corner_count(q); ++k) outlined.outline.push_back(mesh.corners[q][k]);
        outlined.outline_begin.push_back(static_cast<std::uint32_t>(outlined.outline.size()));
    }
    for (const Reconstruction reconstruction : {Reconstruction::linear, Reconstruction::average}) {
        const DisplayMesh a = build_display_mesh(mesh, {.reconstruction = reconstruction});
        const DisplayMesh b = build_display_mesh(outlined, {.reconstruction = reconstruction});
        EXPECT_EQ(a.positions, b.positions);
        EXPECT_EQ(a.normals, b.normals);
        EXPECT_EQ(a.triangles, b.triangles);
        EXPECT_EQ(a.triangle_patch, b.triangle_patch);
        EXPECT_EQ(a.weight_begin, b.weight_begin);
        EXPECT_EQ(a.weight_patch, b.weight_patch);
        EXPECT_EQ(a.weight, b.weight);
    }
}

}  // namespace
}  // namespace rad
