#include "scene/coplanar_emitters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include "rad/geometry/polygon.hpp"
#include "rad/scene/scene.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

// Polygons within this share of the scene's diagonal of one plane lie in it.
constexpr double kPlaneTolerance = 1e-6;
// Unit normals whose dot product is at least 1 minus this are parallel.
constexpr double kParallelTolerance = 1e-9;

struct PlanarPolygon {
    std::uint32_t polygon = 0;
    glm::dvec3 normal{0.0};  // unit, front
    double offset = 0.0;     // normal · x = offset in the plane
    BoundingBox box;
};

using PlaneKey = std::array<std::int64_t, 4>;

class CoplanarFinder {
  public:
    explicit CoplanarFinder(const PolygonSoup& soup) : soup_(soup) {
        BoundingBox box;
        for (const glm::dvec3& p : soup.positions) box.extend(p);
        diagonal_ = glm::length(box.extent());
        tolerance_ = kPlaneTolerance * diagonal_;
    }

    double diagonal() const { return diagonal_; }

    // Indexes the planar emitting polygons by plane; returns whether there are any.
    bool index_emitters() {
        for (std::uint32_t i = 0; i < soup_.polygons.size(); ++i) {
            if (!soup_.groups[soup_.polygons[i].group].material.emits()) continue;
            if (std::optional<PlanarPolygon> p = planar(i)) {
                emitters_by_plane_[key(*p, 0)].push_back(emitters_.size());
                emitters_.push_back(*p);
            }
        }
        return !emitters_.empty();
    }

    // Every (emitter, non-emitting polygon) pair, the emitter by its index, that lie in one plane, face the
    // same way and overlap with positive area. One pass over the polygons, each looked up among the emitters
    // of its plane: the work grows with the polygons and the memory with the emitters.
    std::vector<std::pair<std::size_t, std::uint32_t>> overlaps() const {
        std::vector<std::pair<std::size_t, std::uint32_t>> out;
        for (std::uint32_t i = 0; i < soup_.polygons.size(); ++i) {
            if (soup_.groups[soup_.polygons[i].group].material.emits()) continue;
            const std::optional<PlanarPolygon> c = planar(i);
            if (!c) continue;
            for (std::int64_t shift = -1; shift <= 1; ++shift) {
                const auto bucket = emitters_by_plane_.find(key(*c, shift));
                if (bucket == emitters_by_plane_.end()) continue;
                for (std::size_t k : bucket->second) {
                    const PlanarPolygon& e = emitters_[k];
                    if (glm::dot(c->normal, e.normal) < 1.0 - kParallelTolerance) continue;
                    if (std::abs(c->offset - e.offset) > tolerance_) continue;
                    if (!boxes_overlap(c->box, e.box)) continue;
                    if (overlap_in_plane(e, *c)) out.emplace_back(k, c->polygon);
                }
            }
        }
        return out;
    }

    const PlanarPolygon& emitter(std::size_t k) const { return emitters_[k]; }

  private:
    // The polygon's corners without repeats (as in "f 1 2 2 3"), as build_scene takes them.
    std::vector<glm::dvec3> corners(std::uint32_t polygon) const {
        std::vector<glm::dvec3> out;
        for (std::uint32_t v : soup_.polygons[polygon].vertices) {
            if (out.empty() || out.back() != soup_.positions[v]) out.push_back(soup_.positions[v]);
        }
        while (out.size() > 1 && out.front() == out.back()) out.pop_back();
        return out;
    }

    std::optional<PlanarPolygon> planar(std::uint32_t i) const {
        const std::vector<glm::dvec3> points = corners(i);
        if (points.size() < 3) return std::nullopt;
        const glm::dvec3 n = newell_normal(points);
        const double twice_area = glm::length(n);
        if (!(twice_area > tolerance_ * tolerance_)) return std::nullopt;
        PlanarPolygon p;
        p.polygon = i;
        p.normal = n / twice_area;
        glm::dvec3 centre(0.0);
        for (const glm::dvec3& q : points) {
            centre += q;
            p.box.extend(q);
        }
        p.offset = glm::dot(p.normal, centre / static_cast<double>(points.size()));
        for (const glm::dvec3& q : points) {
            if (std::abs(glm::dot(p.normal, q) - p.offset) > tolerance_) return std::nullopt;
        }
        return p;
    }

    // Normals on a 1e-6 grid and the offset on the tolerance's grid: polygons in one plane share a key, or
    // (offsets within the tolerance straddling a grid line) have neighbouring ones.
    PlaneKey key(const PlanarPolygon& p, std::int64_t shift) const {
        auto grid = [](double x, double step) {
            const double q = std::clamp(x / step, -1e18, 1e18);  // a scene far out for its size: no overflow
            return static_cast<std::int64_t>(std::llround(q));
        };
        return {grid(p.normal.x, 1e-6), grid(p.normal.y, 1e-6), grid(p.normal.z, 1e-6),
                grid(p.offset, tolerance_ > 0.0 ? tolerance_ : 1.0) + shift};
    }

    bool boxes_overlap(const BoundingBox& a, const BoundingBox& b) const {
        for (int k = 0; k < 3; ++k) {
            if (a.max[k] < b.min[k] - tolerance_ || b.max[k] < a.min[k] - tolerance_) return false;
        }
        return true;
    }

    using Triangle2 = std::array<glm::dvec2, 3>;

    // The polygon's triangles in the plane's coordinates.
    std::vector<Triangle2> triangles_in(const Frame& frame, std::uint32_t polygon) const {
        const std::vector<glm::dvec3> points = corners(polygon);
        std::vector<Triangle2> out;
        for (const auto& t : triangulate_polygon(points)) {
            Triangle2 flat;
            for (int k = 0; k < 3; ++k) {
                flat[k] = {glm::dot(frame.tangent, points[t[k]]), glm::dot(frame.bitangent, points[t[k]])};
            }
            out.push_back(flat);
        }
        return out;
    }

    // Separating axes: two triangles overlap with positive area unless, along the normal of one of their
    // edges, their projections overlap by no more than the tolerance (touching is not overlapping).
    bool triangles_overlap(const Triangle2& a, const Triangle2& b) const {
        for (const Triangle2* t : {&a, &b}) {
            for (int k = 0; k < 3; ++k) {
                const glm::dvec2 edge = (*t)[(k + 1) % 3] - (*t)[k];
                const double length = glm::length(edge);
                if (!(length > 0.0)) continue;
                const glm::dvec2 axis(-edge.y / length, edge.x / length);
                constexpr double kInf = std::numeric_limits<double>::infinity();
                double a_lo = kInf, a_hi = -kInf, b_lo = kInf, b_hi = -kInf;
                for (int m = 0; m < 3; ++m) {
                    a_lo = std::min(a_lo, glm::dot(axis, a[m]));
                    a_hi = std::max(a_hi, glm::dot(axis, a[m]));
                    b_lo = std::min(b_lo, glm::dot(axis, b[m]));
                    b_hi = std::max(b_hi, glm::dot(axis, b[m]));
                }
                if (a_hi <= b_lo + tolerance_ || b_hi <= a_lo + tolerance_) return false;
            }
        }
        return true;
    }

    bool overlap_in_plane(const PlanarPolygon& e, const PlanarPolygon& c) const {
        const Frame frame = frame_around(e.normal);
        const std::vector<Triangle2> et = triangles_in(frame, e.polygon);
        const std::vector<Triangle2> ct = triangles_in(frame, c.polygon);
        for (const Triangle2& a : et) {
            for (const Triangle2& b : ct) {
                if (triangles_overlap(a, b)) return true;
            }
        }
        return false;
    }

    const PolygonSoup& soup_;
    double diagonal_ = 0.0;
    double tolerance_ = 0.0;
    std::vector<PlanarPolygon> emitters_;
    std::map<PlaneKey, std::vector<std::size_t>> emitters_by_plane_;  // indices into emitters_
};

std::string lift_warning(const PolygonSoup& soup, std::uint32_t emitter_group, std::uint32_t covered_group,
                         double lift) {
    std::ostringstream out;
    out << soup.source << ": the emitter '" << soup.groups[emitter_group].name << "' lies in the plane of '"
        << soup.groups[covered_group].name << "', facing the same way, and overlaps it; it is moved " << lift
        << " (" << kCoplanarEmitterLift
        << " of the scene's size) in front of it, so the light is what is seen and lit there";
    return out.str();
}

}  // namespace

std::optional<PolygonSoup> lift_coplanar_emitters(const PolygonSoup& soup,
                                                  std::vector<std::string>& warnings) {
    const bool any_emits =
        std::any_of(soup.groups.begin(), soup.groups.end(), [](const auto& g) { return g.material.emits(); });
    if (!any_emits) return std::nullopt;
    CoplanarFinder finder(soup);
    if (!finder.index_emitters()) return std::nullopt;
    const std::vector<std::pair<std::size_t, std::uint32_t>> overlaps = finder.overlaps();
    if (overlaps.empty()) return std::nullopt;

    std::map<std::uint32_t, glm::dvec3> moves;                // emitting polygon -> its unit normal
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (emitter group, covered group), warned
    for (const auto& [k, covered] : overlaps) {
        const PlanarPolygon& e = finder.emitter(k);
        moves.emplace(e.polygon, e.normal);
        pairs.emplace(soup.polygons[e.polygon].group, soup.polygons[covered].group);
    }

    const double lift = kCoplanarEmitterLift * finder.diagonal();
    for (const auto& [emitter, covered] : pairs)
        warnings.push_back(lift_warning(soup, emitter, covered, lift));
    PolygonSoup out = soup;
    // Corners shared by moved polygons of one surface are moved once and stay shared.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> moved;  // (group, old vertex) -> new
    for (const auto& [polygon, normal] : moves) {
        PolygonSoup::Polygon& p = out.polygons[polygon];
        for (std::uint32_t& v : p.vertices) {
            auto [it, inserted] =
                moved.try_emplace({p.group, v}, static_cast<std::uint32_t>(out.positions.size()));
            if (inserted) out.positions.push_back(soup.positions[v] + lift * normal);
            v = it->second;
        }
    }
    return out;
}

}  // namespace rad
