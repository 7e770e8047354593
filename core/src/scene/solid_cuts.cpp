#include "scene/solid_cuts.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <string>
#include <unordered_map>

#include "rad/geometry/polygon.hpp"
#include "scene/box_grid.hpp"
#include "scene/convex_split.hpp"
#include "scene/solid_components.hpp"
#include "scene/soup_corners.hpp"

namespace rad {

namespace {

// Shares of the scene's diagonal: corners within kOnPlane of a plane lie in it; a piece is tested for lying
// inside a solid at a point kProbeLift in front of its centroid (well inside any solid thicker than a
// micrometre in a room of metres, well outside the plane tolerance).
constexpr double kOnPlane = 1e-6;
constexpr double kProbeLift = 1e-5;
// Pieces smaller than this share of the diagonal squared are slivers of the cutting arithmetic.
constexpr double kSliverArea = 1e-14;
// Work before the search stops (pieces tested against a solid's face, faces a parity ray crosses): a file of
// thousands of solids stacked in one place must not take minutes, and the FZK house and the furnished rooms
// stay well under it. And the pieces one face may be cut into.
constexpr std::size_t kMaxWork = 50'000'000;
constexpr std::size_t kMaxPieces = 1024;
// A generic direction for the parity test, parallel to no face or edge a modeller writes.
const glm::dvec3 kParityDirection = glm::normalize(glm::dvec3(0.3170, 0.8814, 0.3502));

struct Plane {
    glm::dvec3 normal{0.0};
    double offset = 0.0;
};

Plane plane_of(const std::vector<glm::dvec3>& points) {
    const glm::dvec3 n = glm::normalize(newell_normal(points));
    glm::dvec3 mean(0.0);
    for (const glm::dvec3& p : points) mean += p;
    mean /= static_cast<double>(points.size());
    return {n, glm::dot(n, mean)};
}

glm::dvec3 centroid(const std::vector<glm::dvec3>& points) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : points) sum += p;
    return sum / static_cast<double>(points.size());
}

// A polygon as convex parts: itself, or its triangles.
std::vector<std::vector<glm::dvec3>> convex_parts(const std::vector<glm::dvec3>& points) {
    if (is_planar_convex(points)) return {points};
    std::vector<std::vector<glm::dvec3>> out;
    for (const auto& t : triangulate_polygon(points))
        out.push_back({points[t[0]], points[t[1]], points[t[2]]});
    return out;
}

// What a face becomes: its convex pieces and the solids whose faces came near it.
struct FacePieces {
    std::vector<std::vector<glm::dvec3>> pieces;
    std::vector<std::uint32_t> solids;
};

class SolidCutter {
  public:
    SolidCutter(const std::vector<std::vector<glm::dvec3>>& corners, const Solids& solids, double diagonal)
        : corners_(corners),
          solids_(solids),
          tolerance_(kOnPlane * diagonal),
          lift_(kProbeLift * diagonal),
          sliver_(kSliverArea * diagonal * diagonal) {
        planes_.resize(corners.size());
        for (std::size_t i = 0; i < corners.size(); ++i)
            if (!corners[i].empty()) planes_[i] = plane_of(corners[i]);
    }

    // Cuts every face near a solid along that solid's faces.
    std::unordered_map<std::uint32_t, FacePieces> cut(const BoxGrid& grid) {
        std::unordered_map<std::uint32_t, FacePieces> faces;
        std::vector<std::uint32_t> near;
        for (std::uint32_t s = 0; s < solids_.polygons.size(); ++s) {
            for (std::uint32_t g : solids_.polygons[s]) {
                grid.query(corners_[g], tolerance_, near);
                for (std::uint32_t f : near) {
                    if (solids_.of_polygon[f] == s || corners_[f].empty()) continue;
                    FacePieces& face = faces[f];
                    if (face.pieces.empty()) face.pieces = convex_parts(corners_[f]);
                    if (face.solids.empty() || face.solids.back() != s) face.solids.push_back(s);
                    if (face.pieces.size() >= kMaxPieces || over_budget(face.pieces.size())) continue;
                    for (const auto& part : g_parts(g)) cut_face(f, g, part, face);
                }
            }
        }
        return faces;
    }

    // Whether a point in front of the piece lies inside one of the solids near its face.
    bool inside(std::uint32_t face, const FacePieces& pieces, const std::vector<glm::dvec3>& piece) {
        const glm::dvec3 probe = centroid(piece) + lift_ * planes_[face].normal;
        for (std::uint32_t s : pieces.solids)
            if (!over_budget(solids_.polygons[s].size()) && inside_solid(probe, s)) return true;
        return false;
    }

    double sliver() const { return sliver_; }
    // Whether the work allowed ran out, so that some faces were left as they were.
    bool stopped() const { return stopped_; }

  private:
    // Counts `amount` of work (pieces tested, triangles crossed) and says whether the budget is spent.
    bool over_budget(std::size_t amount) {
        work_ += amount;
        if (work_ > kMaxWork) stopped_ = true;
        return stopped_;
    }

    const std::vector<std::vector<glm::dvec3>>& g_parts(std::uint32_t g) {
        auto [it, added] = parts_.try_emplace(g);
        if (added) it->second = convex_parts(corners_[g]);
        return it->second;
    }

    void cut_face(std::uint32_t f, std::uint32_t g, const std::vector<glm::dvec3>& part, FacePieces& face) {
        const Plane& pf = planes_[f];
        const Plane& pg = planes_[g];
        const double c = glm::dot(pf.normal, pg.normal);
        if (c < -1.0 + 1e-9 && std::abs(pf.offset + pg.offset) <= tolerance_) {
            cut_along_contact(pg, part, face);
        } else if (std::abs(c) < 1.0 - 1e-9) {
            cut_along_crossing(pf, pg, part, face);
        }
    }

    // The solid's face lies on the face, back to back: the face is cut along its outline.
    void cut_along_contact(const Plane& pg, const std::vector<glm::dvec3>& part, FacePieces& face) {
        std::vector<std::vector<glm::dvec3>> next;
        for (auto& piece : face.pieces) {
            std::vector<std::vector<glm::dvec3>> outside;
            std::vector<glm::dvec3> rest = piece;
            for (std::size_t k = 0; k < part.size() && !rest.empty(); ++k) {
                const glm::dvec3 inward =
                    glm::normalize(glm::cross(pg.normal, part[(k + 1) % part.size()] - part[k]));
                ConvexSplit split = split_convex(rest, inward, glm::dot(inward, part[k]), tolerance_);
                if (!split.back.empty()) outside.push_back(std::move(split.back));
                rest = std::move(split.front);
            }
            if (rest.empty() || !(polygon_area(rest) > sliver_) || outside.empty()) {
                next.push_back(std::move(piece));  // no overlap, or the piece lies wholly on the solid
                continue;
            }
            for (auto& o : outside) next.push_back(std::move(o));
            next.push_back(std::move(rest));
        }
        face.pieces = std::move(next);
    }

    // The solid's face crosses the face's plane: pieces its chord passes through are cut along its plane.
    void cut_along_crossing(const Plane& pf, const Plane& pg, const std::vector<glm::dvec3>& part,
                            FacePieces& face) {
        const glm::dvec3 along = glm::normalize(glm::cross(pf.normal, pg.normal));
        double g_lo = 0.0, g_hi = 0.0;
        if (!chord(part, pf, along, g_lo, g_hi)) return;
        std::vector<std::vector<glm::dvec3>> next;
        for (auto& piece : face.pieces) {
            double p_lo = 0.0, p_hi = 0.0;
            if (chord(piece, pg, along, p_lo, p_hi) &&
                std::min(g_hi, p_hi) - std::max(g_lo, p_lo) > tolerance_) {
                ConvexSplit split = split_convex(piece, pg.normal, pg.offset, tolerance_);
                if (!split.front.empty() && !split.back.empty()) {
                    next.push_back(std::move(split.front));
                    next.push_back(std::move(split.back));
                    continue;
                }
            }
            next.push_back(std::move(piece));
        }
        face.pieces = std::move(next);
    }

    // Where a convex polygon that strictly crosses `plane` meets it: a segment, as an interval along `along`.
    bool chord(const std::vector<glm::dvec3>& polygon, const Plane& plane, const glm::dvec3& along,
               double& lo, double& hi) const {
        bool front = false, back = false;
        lo = std::numeric_limits<double>::infinity();
        hi = -lo;
        for (std::size_t k = 0; k < polygon.size(); ++k) {
            const glm::dvec3& a = polygon[k];
            const glm::dvec3& b = polygon[(k + 1) % polygon.size()];
            const double da = glm::dot(plane.normal, a) - plane.offset;
            const double db = glm::dot(plane.normal, b) - plane.offset;
            front = front || da > tolerance_;
            back = back || da < -tolerance_;
            if (std::abs(da) <= tolerance_) {
                lo = std::min(lo, glm::dot(along, a));
                hi = std::max(hi, glm::dot(along, a));
            } else if ((da > tolerance_ && db < -tolerance_) || (da < -tolerance_ && db > tolerance_)) {
                const double t = glm::dot(along, a + da / (da - db) * (b - a));
                lo = std::min(lo, t);
                hi = std::max(hi, t);
            }
        }
        return front && back;
    }

    // Parity of a ray's crossings with the solid's faces (Möller and Trumbore's ray-triangle test).
    bool inside_solid(const glm::dvec3& origin, std::uint32_t s) {
        std::size_t crossings = 0;
        for (std::uint32_t g : solids_.polygons[s]) {
            for (const auto& part : g_parts(g)) {
                for (std::size_t k = 1; k + 1 < part.size(); ++k)
                    if (ray_meets_triangle(origin, part[0], part[k], part[k + 1])) ++crossings;
            }
        }
        return crossings % 2 == 1;
    }

    static bool ray_meets_triangle(const glm::dvec3& o, const glm::dvec3& a, const glm::dvec3& b,
                                   const glm::dvec3& c) {
        const glm::dvec3 e1 = b - a, e2 = c - a;
        const glm::dvec3 p = glm::cross(kParityDirection, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) return false;
        const glm::dvec3 t = o - a;
        const double u = glm::dot(t, p) / det;
        if (u < 0.0 || u > 1.0) return false;
        const glm::dvec3 q = glm::cross(t, e1);
        const double v = glm::dot(kParityDirection, q) / det;
        if (v < 0.0 || u + v > 1.0) return false;
        return glm::dot(e2, q) / det > 0.0;
    }

    const std::vector<std::vector<glm::dvec3>>& corners_;
    const Solids& solids_;
    const double tolerance_, lift_, sliver_;
    std::vector<Plane> planes_;
    std::size_t work_ = 0;
    bool stopped_ = false;
    std::unordered_map<std::uint32_t, std::vector<std::vector<glm::dvec3>>> parts_;
};

// Texture coordinates at a point of a planar polygon, by the affine map its first three corners that span
// a triangle define.
glm::dvec2 texcoord_at(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec2>& uv,
                       const glm::dvec3& x) {
    for (std::size_t k = 2; k < points.size(); ++k) {
        const glm::dvec3 e1 = points[1] - points[0], e2 = points[k] - points[0];
        const glm::dvec3 n = glm::cross(e1, e2);
        const double nn = glm::dot(n, n);
        if (!(nn > 0.0)) continue;
        const glm::dvec3 d = x - points[0];
        const double u = glm::dot(glm::cross(d, e2), n) / nn;
        const double v = glm::dot(glm::cross(e1, d), n) / nn;
        return uv[0] + u * (uv[1] - uv[0]) + v * (uv[k] - uv[0]);
    }
    return uv[0];
}

// The soup with each changed face replaced by its kept pieces. New corners are shared between pieces.
PolygonSoup with_pieces(const PolygonSoup& soup, const std::unordered_map<std::uint32_t, FacePieces>& faces,
                        const std::vector<std::vector<bool>>& kept) {
    PolygonSoup out;
    out.source = soup.source;
    out.positions = soup.positions;
    out.texcoords = soup.texcoords;
    out.groups = soup.groups;
    std::unordered_map<glm::dvec3, std::uint32_t, PositionHash> added;
    for (std::uint32_t i = 0; i < soup.polygons.size(); ++i) {
        const PolygonSoup::Polygon& polygon = soup.polygons[i];
        const auto it = faces.find(i);
        if (it == faces.end() || kept[i].empty()) {
            out.polygons.push_back(polygon);
            continue;
        }
        const Corners corners = polygon_corners(soup, polygon);
        const std::vector<glm::dvec3> points = corner_positions(soup, corners.vertices);
        for (std::size_t k = 0; k < it->second.pieces.size(); ++k) {
            if (!kept[i][k]) continue;
            PolygonSoup::Polygon piece{{}, polygon.group};
            for (const glm::dvec3& x : it->second.pieces[k]) {
                const auto corner = std::find(points.begin(), points.end(), x);
                if (corner != points.end()) {
                    piece.vertices.push_back(corners.vertices[corner - points.begin()]);
                } else {
                    auto [at, inserted] =
                        added.try_emplace(x, static_cast<std::uint32_t>(out.positions.size()));
                    if (inserted) out.positions.push_back(x);
                    piece.vertices.push_back(at->second);
                }
                if (!corners.uv.empty()) {
                    piece.texcoords.push_back(static_cast<std::uint32_t>(out.texcoords.size()));
                    out.texcoords.push_back(texcoord_at(points, corners.uv, x));
                }
            }
            out.polygons.push_back(std::move(piece));
        }
    }
    return out;
}

}  // namespace

std::optional<PolygonSoup> cut_faces_at_solids(const PolygonSoup& soup, std::vector<std::string>& warnings) {
    std::vector<std::vector<glm::dvec3>> corners(soup.polygons.size());
    BoundingBox box;
    for (const glm::dvec3& p : soup.positions) box.extend(p);
    const double diagonal = glm::length(box.extent());
    for (std::size_t i = 0; i < soup.polygons.size(); ++i) {
        corners[i] = polygon_points(soup, static_cast<std::uint32_t>(i));
        if (corners[i].size() < 3 || !(polygon_area(corners[i]) > kSliverArea * diagonal * diagonal))
            corners[i].clear();
    }
    // Solids are told apart by their groups' names: a file repeats a name for each change of material.
    std::unordered_map<std::string, std::uint32_t> names;
    std::vector<std::uint32_t> name_of(soup.groups.size());
    for (std::size_t g = 0; g < soup.groups.size(); ++g)
        name_of[g] =
            names.try_emplace(soup.groups[g].name, static_cast<std::uint32_t>(names.size())).first->second;
    std::vector<std::uint32_t> groups(soup.polygons.size());
    for (std::size_t i = 0; i < soup.polygons.size(); ++i) groups[i] = name_of[soup.polygons[i].group];
    const Solids solids = find_solids(corners, groups);
    if (solids.polygons.empty()) return std::nullopt;

    SolidCutter cutter(corners, solids, diagonal);
    std::unordered_map<std::uint32_t, FacePieces> faces = cutter.cut(BoxGrid(corners, box));
    // Per face, which pieces stay: none listed for a face left whole.
    std::vector<std::vector<bool>> kept(soup.polygons.size());
    std::size_t cut = 0, dropped = 0;
    for (auto& [f, face] : faces) {
        std::vector<bool> keep(face.pieces.size(), true);
        // A face is cut only where a part of it is dropped: pieces that all stay are the face, whole.
        bool changed = false;
        for (std::size_t k = 0; k < face.pieces.size(); ++k) {
            keep[k] =
                polygon_area(face.pieces[k]) > cutter.sliver() && !cutter.inside(f, face, face.pieces[k]);
            if (!keep[k]) {
                changed = true;
                ++dropped;
            }
        }
        if (!changed) continue;
        ++cut;
        kept[f] = std::move(keep);
    }
    if (cutter.stopped()) {
        warnings.push_back(
            soup.source + ": the search for faces inside closed solids stopped after " +
            std::to_string(kMaxWork) +
            " steps; faces it did not reach may still reach into solids and let light through");
    }
    if (cut == 0) return std::nullopt;
    warnings.push_back(
        soup.source + ": " + std::to_string(cut) +
        " face(s) reach into closed solids (a wall through a wall, a floor under a wall, a leg "
        "through a floor): cut where they enter them, and " +
        std::to_string(dropped) + " part(s) inside the solids dropped, so no light passes through");
    return with_pieces(soup, faces, kept);
}

}  // namespace rad
