#include "scene/coplanar_faces.hpp"

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
// Exact overlap tests before the search stops: a real scene has a few thousand coplanar overlaps at most, and
// a file of thousands of stacked faces must not take minutes.
constexpr std::size_t kMaxOverlapTests = 200'000;
// Pairs of surfaces named in warnings one by one; the rest are counted in one more.
constexpr std::size_t kListedPairs = 8;

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
    // The polygon's unit normal, plane and box; nothing for a polygon that is not planar.
    std::optional<PlanarPolygon> planar_polygon(std::uint32_t i) const { return planar(i); }

    // Every pair of polygons of different surfaces that lie in one plane, face the same way and overlap with
    // positive area. The planar polygons are bucketed by plane; within a bucket (and its neighbour on the
    // offset's grid, where a plane straddles a grid line) a sweep along the axis of the boxes' largest
    // extent compares only polygons whose boxes meet along it, and only buckets holding two surfaces at all.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlaps() const {
        std::map<PlaneKey, std::vector<PlanarPolygon>> by_plane;
        for (std::uint32_t i = 0; i < soup_.polygons.size(); ++i) {
            if (std::optional<PlanarPolygon> p = planar(i)) by_plane[key(*p, 0)].push_back(*p);
        }
        std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
        for (const auto& [k, bucket] : by_plane) {
            PlaneKey next = k;
            ++next[3];
            const auto neighbour = by_plane.find(next);
            std::vector<Candidate> candidates;
            for (const PlanarPolygon& p : bucket) candidates.push_back({&p, false});
            if (neighbour != by_plane.end()) {
                for (const PlanarPolygon& p : neighbour->second) candidates.push_back({&p, true});
            }
            sweep(candidates, out);
            if (stopped_) break;
        }
        return out;
    }

    // The search stopped at kMaxOverlapTests: overlaps may be left.
    bool stopped() const { return stopped_; }

  private:
    struct Candidate {
        const PlanarPolygon* polygon;
        bool from_neighbour;  // its own bucket compares it with its own polygons
    };

    std::uint32_t group_of(const PlanarPolygon& p) const { return soup_.polygons[p.polygon].group; }

    void sweep(std::vector<Candidate>& candidates,
               std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) const {
        const std::uint32_t first_group = group_of(*candidates.front().polygon);
        const bool one_surface = std::all_of(candidates.begin(), candidates.end(), [&](const Candidate& c) {
            return group_of(*c.polygon) == first_group;
        });
        if (one_surface) return;
        BoundingBox all;
        for (const Candidate& c : candidates) {
            all.extend(c.polygon->box.min);
            all.extend(c.polygon->box.max);
        }
        const glm::dvec3 extent = all.extent();
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
        std::sort(candidates.begin(), candidates.end(), [&](const Candidate& a, const Candidate& b) {
            return a.polygon->box.min[axis] < b.polygon->box.min[axis];
        });
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            const PlanarPolygon& a = *candidates[i].polygon;
            for (std::size_t j = i + 1; j < candidates.size(); ++j) {
                const PlanarPolygon& b = *candidates[j].polygon;
                if (b.box.min[axis] > a.box.max[axis] + tolerance_) break;
                if (candidates[i].from_neighbour && candidates[j].from_neighbour) continue;
                if (group_of(a) == group_of(b)) continue;
                if (glm::dot(a.normal, b.normal) < 1.0 - kParallelTolerance) continue;
                if (std::abs(a.offset - b.offset) > tolerance_) continue;
                if (!boxes_overlap(a.box, b.box)) continue;
                if (++tests_ > kMaxOverlapTests) {
                    stopped_ = true;
                    return;
                }
                if (overlap_in_plane(a, b)) out.emplace_back(a.polygon, b.polygon);
            }
        }
    }

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
    mutable std::size_t tests_ = 0;
    mutable bool stopped_ = false;
};

// Per surface (group), the area of its polygons: the smaller of two coplanar surfaces is the one on top.
std::vector<double> group_areas(const PolygonSoup& soup) {
    std::vector<double> area(soup.groups.size(), 0.0);
    for (const PolygonSoup::Polygon& p : soup.polygons) {
        std::vector<glm::dvec3> points;
        for (std::uint32_t v : p.vertices) points.push_back(soup.positions[v]);
        if (points.size() >= 3) area[p.group] += 0.5 * glm::length(newell_normal(points));
    }
    return area;
}

// Which of two overlapping polygons moves in front: the emitter's, else the smaller surface's (the first
// where the two tie).
std::uint32_t covering(const PolygonSoup& soup, const std::vector<double>& area, std::uint32_t a,
                       std::uint32_t b) {
    const PolygonSoup::Group& ga = soup.groups[soup.polygons[a].group];
    const PolygonSoup::Group& gb = soup.groups[soup.polygons[b].group];
    if (ga.material.emits() != gb.material.emits()) return ga.material.emits() ? a : b;
    return area[soup.polygons[b].group] < area[soup.polygons[a].group] ? b : a;
}

std::string lift_warning(const PolygonSoup& soup, std::uint32_t moved_group, std::uint32_t covered_group,
                         double lift) {
    const PolygonSoup::Group& moved = soup.groups[moved_group];
    std::ostringstream out;
    out << soup.source << ": " << (moved.material.emits() ? "the emitter '" : "'") << moved.name
        << "' lies in the plane of '" << soup.groups[covered_group].name
        << "', facing the same way, and overlaps it; it is moved " << lift << " (" << kCoplanarLift
        << " of the scene's size) in front of it, so " << (moved.material.emits() ? "the light" : "it")
        << " is what is seen and lit there";
    return out.str();
}

std::string stopped_warning(const PolygonSoup& soup) {
    return soup.source + ": more than " + std::to_string(kMaxOverlapTests) +
           " pairs of coplanar faces to compare; the search stopped there, and faces it did not reach may "
           "still "
           "lie in one another's plane";
}

}  // namespace

std::optional<PolygonSoup> lift_coplanar_faces(const PolygonSoup& soup, std::vector<std::string>& warnings) {
    if (soup.groups.size() < 2) return std::nullopt;
    const CoplanarFinder finder(soup);
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> overlaps = finder.overlaps();
    if (overlaps.empty() && finder.stopped()) warnings.push_back(stopped_warning(soup));
    if (overlaps.empty()) return std::nullopt;

    const std::vector<double> area = group_areas(soup);
    std::map<std::uint32_t, glm::dvec3> moves;                // moved polygon -> its unit normal
    std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (moved group, covered group), warned
    for (const auto& [a, b] : overlaps) {
        const std::uint32_t top = covering(soup, area, a, b);
        const std::uint32_t under = top == a ? b : a;
        // A polygon both covers and is covered only in a stack of three or more; it moves once.
        if (moves.count(top) == 0) moves.emplace(top, finder.planar_polygon(top)->normal);
        pairs.emplace(soup.polygons[top].group, soup.polygons[under].group);
    }

    const double lift = kCoplanarLift * finder.diagonal();
    // One warning per pair of names (a file may repeat a group's name), the first kListedPairs of them.
    std::set<std::pair<std::string, std::string>> named;
    std::size_t unlisted = 0;
    for (const auto& [moved, covered] : pairs) {
        if (!named.emplace(soup.groups[moved].name, soup.groups[covered].name).second) continue;
        if (named.size() <= kListedPairs) {
            warnings.push_back(lift_warning(soup, moved, covered, lift));
        } else {
            ++unlisted;
        }
    }
    if (unlisted > 0) {
        warnings.push_back(soup.source + ": " + std::to_string(unlisted) +
                           " more pairs of surfaces lie in one plane, facing the same way, and overlap; the "
                           "covering one of each is moved likewise");
    }
    if (finder.stopped()) warnings.push_back(stopped_warning(soup));
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
