#include "transport/adaptive/adaptive_shadow.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <limits>

#include "rad/geometry/point_polygon_factor.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

constexpr int kLeafPoints = 5;  // up to four corners and the centroid
constexpr int kMaxRays = kLeafPoints * kSourceSamples;

struct LeafPoints {
    std::array<glm::dvec3, kLeafPoints> at{};
    int count = 0;
};

LeafPoints leaf_points(const PatchMesh& mesh, std::size_t i) {
    LeafPoints points;
    const glm::dvec3 centroid = mesh.patches[i].centroid;
    for (int c = 0; c < mesh.corner_count(i); ++c)
        points.at[points.count++] =
            centroid + (1.0 - kCornerPull) * (mesh.points[mesh.corners[i][c]] - centroid);
    points.at[points.count++] = centroid;
    return points;
}

ConvexPolygon base_polygon(const PatchMesh& base, std::uint32_t b) {
    std::array<glm::dvec3, 4> corners{};
    const int n = base.corner_count(b);
    for (int c = 0; c < n; ++c) corners[c] = base.points[base.corners[b][c]];
    return make_convex_polygon(std::span(corners.data(), static_cast<std::size_t>(n)));
}

// The largest unoccluded form factor from the leaf's points to the source's front.
double largest_factor(const LeafPoints& points, const glm::dvec3& normal, const ConvexPolygon& source) {
    double largest = 0.0;
    for (int k = 0; k < points.count; ++k) {
        const ConvexPolygon front = clip_to_front(source, points.at[k], normal);
        if (!front.empty())
            largest = std::max(largest, point_polygon_factor(points.at[k], normal, front.span()));
    }
    return largest;
}

// The irradiance luminance H_i = Σ_j F_ij Y(B_j) of leaf i (its exposed part).
double irradiance(const SolvedLeaves& leaves, std::size_t i) {
    const FormFactorRow row = leaves.system.form_factors.row(i);
    double h = 0.0;
    for (std::size_t k = 0; k < row.size(); ++k)
        h += static_cast<double>(row.values[k]) * luminance(leaves.radiosity[row.columns[k]]);
    return h;
}

// The unoccluded point-to-point kernel cos θ cos θ' / r² between a leaf point and a source point, for d = the
// source point − the leaf point; 0 when either faces away.
double kernel(const glm::dvec3& d, const glm::dvec3& n, const glm::dvec3& ns) {
    const double r2 = glm::dot(d, d);
    return std::max(0.0, glm::dot(d, n)) * std::max(0.0, -glm::dot(d, ns)) / (r2 * r2);
}

// max − min over the leaf's points of the share of the source's light that reaches each: the sample points'
// kernels, the unoccluded over all. Points the source cannot light at all (behind its plane) do not count,
// so a leaf crossing the plane of a source (a wall below the top of a box) is no shadow boundary: its light
// fades there continuously.
double visibility_change(const SolvedLeaves& leaves, std::size_t i, const LeafPoints& points,
                         const ShadowSource& source, const ConvexPolygon& polygon, const ShadowRays& rays) {
    RandomStream random(rays.seed, leaves.elements[i], source.base_patch);
    std::array<glm::dvec2, kSourceSamples> u{};
    stratified_square(random, u);
    const glm::dvec3 n = leaves.mesh.patches[i].normal;
    const glm::dvec3 ns = rays.base.patches[source.base_patch].normal;
    std::array<Ray, kMaxRays> batch{};
    std::array<double, kMaxRays> weight{};
    std::array<int, kMaxRays> point_of{};
    std::size_t count = 0;
    for (const glm::dvec2& s : u) {
        const glm::dvec3 target = point_on_convex_polygon(polygon.span(), s) + rays.offset * ns;
        for (int k = 0; k < points.count; ++k) {
            const glm::dvec3 origin = points.at[k] + rays.offset * n;
            const glm::dvec3 d = target - origin;
            const double w = kernel(d, n, ns);
            if (!(w > 0.0)) continue;
            batch[count] = Ray{origin, 0.0f, d, 1.0f};
            weight[count] = w;
            point_of[count++] = k;
        }
    }
    std::array<std::uint8_t, kMaxRays> blocked{};
    rays.scene.occluded(std::span(batch.data(), count), std::span(blocked.data(), count));
    std::array<double, kLeafPoints> total{}, seen{};
    for (std::size_t r = 0; r < count; ++r) {
        total[point_of[r]] += weight[r];
        if (!blocked[r]) seen[point_of[r]] += weight[r];
    }
    double lo = 1.0, hi = 0.0;
    for (int k = 0; k < points.count; ++k) {
        if (!(total[k] > 0.0)) continue;
        lo = std::min(lo, seen[k] / total[k]);
        hi = std::max(hi, seen[k] / total[k]);
    }
    return std::max(0.0, hi - lo);
}

double leaf_excess(const SolvedLeaves& leaves, std::size_t i, std::span<const ShadowSource> sources,
                   const ShadowRays& rays) {
    const LeafPoints points = leaf_points(leaves.mesh, i);
    const glm::dvec3 n = leaves.mesh.patches[i].normal;
    const double noticeable = kShadowShare * irradiance(leaves, i);
    double excess = 0.0;
    for (const ShadowSource& source : sources) {
        if (source.base_patch == leaves.base_patch(i)) continue;
        const ConvexPolygon polygon = base_polygon(rays.base, source.base_patch);
        const double share = source.luminance * largest_factor(points, n, polygon);
        if (!(share > 0.0)) continue;
        const double share_ratio =
            noticeable > 0.0 ? share / noticeable : std::numeric_limits<double>::infinity();
        // Rays only where they could change the answer: the source is noticeable and could beat the best.
        if (share_ratio < 1.0 || share_ratio <= excess) continue;
        const double change = visibility_change(leaves, i, points, source, polygon, rays) / kVisibilityChange;
        excess = std::max(excess, std::min(change, share_ratio));
    }
    return excess;
}

}  // namespace

std::vector<double> shadow_excess(const SolvedLeaves& leaves, std::span<const ShadowSource> sources,
                                  const ShadowRays& rays, Progress* progress) {
    std::vector<double> excess(leaves.radiosity.size(), 0.0);
    tbb::parallel_for(std::size_t(0), excess.size(), [&](std::size_t i) {
        if (progress && progress->cancelled()) return;
        excess[i] = leaf_excess(leaves, i, sources, rays);
        if (progress) progress->advance();
    });
    return excess;
}

}  // namespace rad
