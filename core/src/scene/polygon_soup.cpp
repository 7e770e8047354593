#include "rad/scene/polygon_soup.hpp"

#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <unordered_map>

#include "rad/geometry/polygon.hpp"
#include "rad/util/error.hpp"
#include "scene/coplanar_faces.hpp"
#include "scene/solid_cuts.hpp"
#include "scene/soup_corners.hpp"

namespace rad {

namespace {

// Below this fraction of the scene's squared size a polygon has no area worth a patch.
constexpr double kZeroAreaFraction = 1e-14;

const SurfaceMesh::TexCoord2D kNoTexcoord(std::numeric_limits<float>::quiet_NaN(),
                                          std::numeric_limits<float>::quiet_NaN());

// Builds one surface's OpenMesh mesh, sharing vertices between faces where OpenMesh can keep the mesh
// manifold and giving a face its own copies of the vertices where it cannot.
class SurfaceBuilder {
  public:
    explicit SurfaceBuilder(const PolygonSoup& soup) : soup_(soup) {}

    // `uv`: the corners' texture coordinates, or empty.
    void add_face(const std::vector<std::uint32_t>& soup_vertices, const std::vector<glm::dvec2>& uv) {
        std::vector<SurfaceMesh::VertexHandle> handles;
        handles.reserve(soup_vertices.size());
        for (std::uint32_t v : soup_vertices) handles.push_back(shared_vertex(v));
        SurfaceMesh::FaceHandle face = add_quietly(handles);
        if (!face.is_valid()) {
            for (std::size_t i = 0; i < handles.size(); ++i) handles[i] = new_vertex(soup_vertices[i]);
            face = add_quietly(handles);
        }
        if (face.is_valid()) set_texcoords(face, handles, uv);
    }

    SurfaceMesh take() { return std::move(mesh_); }
    bool empty() const { return mesh_.n_faces() == 0; }

  private:
    // OpenMesh reports a non-manifold face on its error stream; we handle it, so keep the terminal clean.
    SurfaceMesh::FaceHandle add_quietly(const std::vector<SurfaceMesh::VertexHandle>& handles) {
        omerr().disable();
        const SurfaceMesh::FaceHandle face = mesh_.add_face(handles);
        omerr().enable();
        return face;
    }
    // Texture coordinates live on the halfedges into each corner, so faces meeting at a seam keep their
    // own. Once a surface has any, a face without them gets NaN, which the display reads as "untextured".
    void set_texcoords(SurfaceMesh::FaceHandle face, const std::vector<SurfaceMesh::VertexHandle>& handles,
                       const std::vector<glm::dvec2>& uv) {
        if (uv.empty() && !mesh_.has_halfedge_texcoords2D()) return;
        if (!mesh_.has_halfedge_texcoords2D()) {
            mesh_.request_halfedge_texcoords2D();
            for (auto h : mesh_.halfedges()) mesh_.set_texcoord2D(h, kNoTexcoord);
        }
        for (auto h : mesh_.fh_range(face)) {
            const auto corner = std::find(handles.begin(), handles.end(), mesh_.to_vertex_handle(h));
            const auto k = static_cast<std::size_t>(corner - handles.begin());
            mesh_.set_texcoord2D(h, uv.empty() ? kNoTexcoord : SurfaceMesh::TexCoord2D(uv[k].x, uv[k].y));
        }
    }
    SurfaceMesh::VertexHandle new_vertex(std::uint32_t v) {
        const glm::dvec3& p = soup_.positions[v];
        return mesh_.add_vertex(SurfaceMesh::Point(p.x, p.y, p.z));
    }
    SurfaceMesh::VertexHandle shared_vertex(std::uint32_t v) {
        auto [it, inserted] = shared_.try_emplace(v);
        if (inserted) it->second = new_vertex(v);
        return it->second;
    }

    const PolygonSoup& soup_;
    SurfaceMesh mesh_;
    std::unordered_map<std::uint32_t, SurfaceMesh::VertexHandle> shared_;
};

// A polygon's corners from its lexicographically smallest position on, in its winding: two polygons with
// the same corners in the same turning order have the same key, whatever corner they start from.
std::vector<glm::dvec3> rotated_to_smallest(std::vector<glm::dvec3> points) {
    const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    std::rotate(points.begin(), std::min_element(points.begin(), points.end(), less), points.end());
    return points;
}

std::size_t hash_points(const std::vector<glm::dvec3>& points) {
    std::size_t h = points.size();
    for (const glm::dvec3& p : points) h = h * 0x100000001b3ull ^ PositionHash {}(p);
    return h;
}

// Remembers the polygons seen by a hash of their keys; a repeat (same corners, same winding, any first
// corner) is a duplicate face, which would otherwise put its surface's light in twice. Back-to-back faces
// (opposite windings) are not repeats.
class DuplicateFaces {
  public:
    explicit DuplicateFaces(const PolygonSoup& soup) : soup_(soup) {}

    bool seen_before(std::size_t polygon, const std::vector<glm::dvec3>& points) {
        const std::vector<glm::dvec3> key = rotated_to_smallest(points);
        const std::size_t h = hash_points(key);
        auto [first, last] = seen_.equal_range(h);
        for (auto it = first; it != last; ++it)
            if (key_of(it->second) == key) return true;
        seen_.emplace(h, polygon);
        return false;
    }

  private:
    std::vector<glm::dvec3> key_of(std::size_t polygon) const {
        return rotated_to_smallest(
            corner_positions(soup_, without_repeats(soup_, soup_.polygons[polygon].vertices)));
    }

    const PolygonSoup& soup_;
    std::unordered_multimap<std::size_t, std::size_t> seen_;  // key hash -> polygon
};

double scene_size_squared(const PolygonSoup& soup) {
    BoundingBox box;
    for (const auto& p : soup.positions) box.extend(p);
    const double d = glm::length(box.extent());
    return d * d;
}

// The soup without the polygons that repeat an earlier one (with area), and their count; nothing when none
// does. Done before coplanar faces are lifted: two copies in different groups would otherwise be taken for a
// rug on a floor, one moved in front of the other, and both would stay (a duplicated lamp emitting twice).
std::optional<PolygonSoup> without_duplicate_faces(const PolygonSoup& soup, double min_area,
                                                   std::size_t& duplicates) {
    DuplicateFaces seen(soup);
    std::vector<bool> repeat(soup.polygons.size(), false);
    duplicates = 0;
    for (std::size_t index = 0; index < soup.polygons.size(); ++index) {
        const std::vector<glm::dvec3> points = polygon_points(soup, static_cast<std::uint32_t>(index));
        if (points.size() < 3 || !(polygon_area(points) > min_area)) continue;
        if (seen.seen_before(index, points)) {
            repeat[index] = true;
            ++duplicates;
        }
    }
    if (duplicates == 0) return std::nullopt;
    PolygonSoup out;
    out.source = soup.source;
    out.positions = soup.positions;
    out.texcoords = soup.texcoords;
    out.groups = soup.groups;
    out.polygons.reserve(soup.polygons.size() - duplicates);
    for (std::size_t index = 0; index < soup.polygons.size(); ++index)
        if (!repeat[index]) out.polygons.push_back(soup.polygons[index]);
    return out;
}

// A polygon of the soup that has area and repeats no earlier one.
struct KeptPolygon {
    std::uint32_t index = 0;  // into soup.polygons
    bool paired = false;      // a later or earlier kept polygon is its back: the same corners, reversed
};

// Pairs the kept polygons that lie back to back (a real file's way of building a two-sided part, such as a
// lamp shade or a curtain) and returns the number of pairs.
std::size_t pair_back_to_back(const PolygonSoup& soup, std::vector<KeptPolygon>& kept) {
    std::unordered_multimap<std::size_t, std::size_t> by_key;  // key hash -> position in kept
    by_key.reserve(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
        by_key.emplace(hash_points(rotated_to_smallest(polygon_points(soup, kept[k].index))), k);
    std::size_t pairs = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
        if (kept[k].paired) continue;
        std::vector<glm::dvec3> reversed = polygon_points(soup, kept[k].index);
        std::reverse(reversed.begin(), reversed.end());
        const std::vector<glm::dvec3> key = rotated_to_smallest(std::move(reversed));
        auto [first, last] = by_key.equal_range(hash_points(key));
        for (auto it = first; it != last; ++it) {
            KeptPolygon& other = kept[it->second];
            if (other.paired || it->second == k) continue;
            if (rotated_to_smallest(polygon_points(soup, other.index)) != key) continue;
            kept[k].paired = other.paired = true;
            ++pairs;
            break;
        }
    }
    return pairs;
}

// The faces of one group: one-sided ones, and the two sides of its two-sided ones (faces paired back to
// back in the file, or every face of a two-sided material, whose back this adds).
struct GroupBuilders {
    explicit GroupBuilders(const PolygonSoup& soup) : one_sided(soup), front(soup), back(soup) {}
    SurfaceBuilder one_sided, front, back;
};

// Adds the polygon's faces (itself, or its triangles where it is not planar and convex) to `front` and,
// when `back` is given, the same faces reversed to it.
void add_polygon(const PolygonSoup& soup, const Corners& corners, double min_area, SurfaceBuilder& front,
                 SurfaceBuilder* back) {
    const auto add = [&](std::vector<std::uint32_t> face, std::vector<glm::dvec2> uv) {
        front.add_face(face, uv);
        if (!back) return;
        std::reverse(face.begin(), face.end());
        std::reverse(uv.begin(), uv.end());
        back->add_face(face, uv);
    };
    const std::vector<glm::dvec3> points = corner_positions(soup, corners.vertices);
    if (is_planar_convex(points)) {
        add(corners.vertices, corners.uv);
        return;
    }
    for (const auto& t : triangulate_polygon(points)) {
        std::vector<std::uint32_t> tri{corners.vertices[t[0]], corners.vertices[t[1]],
                                       corners.vertices[t[2]]};
        std::vector<glm::dvec2> uv;
        if (!corners.uv.empty()) uv = {corners.uv[t[0]], corners.uv[t[1]], corners.uv[t[2]]};
        if (polygon_area(corner_positions(soup, tri)) > min_area) add(std::move(tri), std::move(uv));
    }
}

void add_surface(Scene& scene, const PolygonSoup::Group& group, SurfaceBuilder& builder, bool back_to_back,
                 const std::string& suffix) {
    if (builder.empty()) return;
    scene.surfaces.push_back(Surface{group.name + suffix, group.material, builder.take(), back_to_back});
}

}  // namespace

Scene build_scene(const PolygonSoup& input) {
    const double min_area = kZeroAreaFraction * scene_size_squared(input);
    std::size_t duplicates = 0;
    const std::optional<PolygonSoup> unique = without_duplicate_faces(input, min_area, duplicates);
    // Solids are found before coplanar faces are lifted, which would open them.
    std::vector<std::string> lift_warnings;
    const std::optional<PolygonSoup> cut = cut_faces_at_solids(unique ? *unique : input, lift_warnings);
    const PolygonSoup& uncut = cut ? *cut : unique ? *unique : input;
    const std::optional<PolygonSoup> lifted = lift_coplanar_faces(uncut, lift_warnings);
    const PolygonSoup& soup = lifted ? *lifted : uncut;
    std::size_t dropped = 0;
    std::vector<KeptPolygon> kept;

    for (std::size_t index = 0; index < soup.polygons.size(); ++index) {
        const std::vector<glm::dvec3> points = polygon_points(soup, static_cast<std::uint32_t>(index));
        if (points.size() < 3 || !(polygon_area(points) > min_area)) {
            ++dropped;
        } else {
            kept.push_back({static_cast<std::uint32_t>(index)});
        }
    }
    const std::size_t pairs = pair_back_to_back(soup, kept);

    std::vector<GroupBuilders> builders(soup.groups.size(), GroupBuilders(soup));
    for (const KeptPolygon& polygon : kept) {
        const PolygonSoup::Polygon& p = soup.polygons[polygon.index];
        GroupBuilders& group = builders[p.group];
        const Corners corners = polygon_corners(soup, p);
        if (polygon.paired) {
            add_polygon(soup, corners, min_area, group.front, nullptr);
        } else if (soup.groups[p.group].material.two_sided) {
            add_polygon(soup, corners, min_area, group.front, &group.back);
        } else {
            add_polygon(soup, corners, min_area, group.one_sided, nullptr);
        }
    }

    Scene scene;
    scene.source = soup.source;
    for (std::size_t g = 0; g < soup.groups.size(); ++g) {
        add_surface(scene, soup.groups[g], builders[g].one_sided, false, "");
        add_surface(scene, soup.groups[g], builders[g].front, true, "");
        add_surface(scene, soup.groups[g], builders[g].back, true, " (back)");
    }
    if (dropped > 0) {
        scene.warnings.push_back(soup.source + ": dropped " + std::to_string(dropped) +
                                 " face(s) with zero area or fewer than three distinct corners");
    }
    if (duplicates > 0) {
        scene.warnings.push_back(
            soup.source + ": dropped " + std::to_string(duplicates) +
            " duplicate face(s) (the same corners as an earlier face, in the same cyclic order)");
    }
    if (pairs > 0) {
        scene.warnings.push_back(soup.source + ": " + std::to_string(pairs) +
                                 " pair(s) of back-to-back faces (the same corners in opposite orders) are "
                                 "read as two-sided surfaces, each side lit on its own");
    }
    scene.warnings.insert(scene.warnings.end(), lift_warnings.begin(), lift_warnings.end());
    if (scene.surfaces.empty()) throw InputError(soup.source + ": the scene has no faces with area");
    if (!has_emitter(scene)) scene.warnings.push_back(no_emitter_warning(soup.source));
    return scene;
}

}  // namespace rad
