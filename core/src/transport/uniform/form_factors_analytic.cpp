#include "transport/uniform/form_factors_analytic.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <vector>

#include "sampling/patch_shapes.hpp"
#include "sampling/sampling.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"

namespace rad {

namespace {

struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

Sphere bounding_sphere(std::span<const glm::dvec3> corners) {
    Sphere s;
    for (const glm::dvec3& p : corners) s.centre += p;
    s.centre /= static_cast<double>(corners.size());
    for (const glm::dvec3& p : corners) s.radius = std::max(s.radius, glm::length(p - s.centre));
    return s;
}

// A lower bound on the distance from a piece of the receiver to the (clipped) source polygon: the largest of
// three lower bounds, each weak somewhere: the piece's distance from the source's plane, the source's
// distance from the receiver's plane, and the gap between their bounding spheres.
class SourceDistance {
  public:
    SourceDistance(const ConvexPolygon& source, const glm::dvec3& source_normal,
                   const glm::dvec3& receiver_point, const glm::dvec3& receiver_normal)
        : sphere_(bounding_sphere(source.span())), normal_(source_normal), plane_point_(source.corners[0]) {
        source_to_receiver_plane_ = std::numeric_limits<double>::infinity();
        for (const glm::dvec3& p : source.span()) {
            source_to_receiver_plane_ =
                std::min(source_to_receiver_plane_, glm::dot(receiver_normal, p - receiver_point));
        }
    }

    double operator()(std::span<const glm::dvec3> piece) const {
        double to_source_plane = std::numeric_limits<double>::infinity();
        for (const glm::dvec3& p : piece)
            to_source_plane = std::min(to_source_plane, glm::dot(normal_, p - plane_point_));
        const Sphere s = bounding_sphere(piece);
        const double sphere_gap = glm::length(s.centre - sphere_.centre) - s.radius - sphere_.radius;
        return std::max({to_source_plane, source_to_receiver_plane_, sphere_gap, 0.0});
    }

    // How much the receiver piece's height above the source's plane varies over it, relative to its least
    // height. The kernel is proportional to that height, which a one-point rule gets wrong where the two
    // patches are nearly coplanar (grazing pairs) even when they lie far apart.
    double height_spread(std::span<const glm::dvec3> piece) const {
        double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
        for (const glm::dvec3& p : piece) {
            const double h = glm::dot(normal_, p - plane_point_);
            lo = std::min(lo, h);
            hi = std::max(hi, h);
        }
        return lo > 0.0 ? (hi - lo) / lo : std::numeric_limits<double>::infinity();
    }

  private:
    Sphere sphere_;
    glm::dvec3 normal_;
    glm::dvec3 plane_point_;
    double source_to_receiver_plane_;
};

// The unoccluded F from the receiver piece `receiver` (in patch i's plane, area taken from patch i) to
// `source`.
double unoccluded_factor(const PatchShape& i, const ConvexPolygon& receiver, const PatchShape& j,
                         const ConvexPolygon& source, const AdaptiveRule& rule) {
    return unoccluded_form_factor(receiver, i.centroid, i.normal, i.area, source, j.normal, rule);
}

struct Candidate {
    std::uint32_t column;
    double unoccluded;
};

struct AnalyticScratch {
    std::vector<Candidate> candidates;
    std::vector<Ray> rays;
    std::vector<std::uint8_t> blocked;
    std::vector<glm::dvec2> strata;
};

}  // namespace

double unoccluded_form_factor(const ConvexPolygon& receiver_part, const glm::dvec3& receiver_centroid,
                              const glm::dvec3& receiver_normal, double receiver_area,
                              const ConvexPolygon& source, const glm::dvec3& source_normal,
                              const AdaptiveRule& rule) {
    auto kernel = [&](const glm::dvec3& x) {
        return point_polygon_factor(x, receiver_normal, source.span());
    };
    SourceDistance distance(source, source_normal, receiver_centroid, receiver_normal);
    const AdaptiveIntegral integral(rule, kernel, distance);
    return integral.over(receiver_part) / receiver_area;
}

RowFunction analytic_rows(const PatchMesh& patches, const RayScene& scene, int rays, std::uint64_t seed,
                          const AdaptiveRule& rule) {
    auto shapes = std::make_shared<const std::vector<PatchShape>>(patch_shapes(patches));
    auto scratch = std::make_shared<tbb::enumerable_thread_specific<AnalyticScratch>>();
    const double offset = ray_offset(patches);
    const auto per_pair = static_cast<std::size_t>(rays);
    return [&scene, shapes, scratch, per_pair, seed, offset, rule](
               std::uint32_t i, std::vector<RowEntry>& entries, RowStats& stats) {
        const std::vector<PatchShape>& shape = *shapes;
        AnalyticScratch& s = scratch->local();
        s.candidates.clear();
        s.rays.clear();
        s.strata.resize(2 * per_pair);
        const PatchShape& pi = shape[i];
        for (std::uint32_t j = 0; j < shape.size(); ++j) {
            if (j == i) continue;
            const PatchShape& pj = shape[j];
            const ConvexPolygon source = clip_to_front(pj.polygon, pi.centroid, pi.normal);
            if (source.empty()) continue;
            const ConvexPolygon receiver = clip_to_front(pi.polygon, pj.centroid, pj.normal);
            if (receiver.empty()) continue;
            const double unoccluded = unoccluded_factor(pi, receiver, pj, source, rule);
            if (!(unoccluded > 0.0)) continue;
            s.candidates.push_back({j, unoccluded});
            RandomStream random(seed, std::min(i, j), std::max(i, j));
            if (i < j) {
                append_shadow_rays(receiver, pi.normal, source, pj.normal, random, offset, s.strata, s.rays);
            } else {
                append_shadow_rays(source, pj.normal, receiver, pi.normal, random, offset, s.strata, s.rays);
            }
        }
        s.blocked.resize(s.rays.size());
        scene.occluded(s.rays, s.blocked);
        stats.rays += s.rays.size();
        for (std::size_t c = 0; c < s.candidates.size(); ++c) {
            const auto first = s.blocked.begin() + static_cast<std::ptrdiff_t>(c * per_pair);
            const auto open =
                std::count(first, first + static_cast<std::ptrdiff_t>(per_pair), std::uint8_t{0});
            const double visible = static_cast<double>(open) / static_cast<double>(per_pair);
            if (visible > 0.0)
                entries.push_back({s.candidates[c].column, s.candidates[c].unoccluded * visible});
        }
    };
}

}  // namespace rad
