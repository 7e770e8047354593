#include "transport/hierarchical/hierarchical_links.hpp"

#include "rad/geometry/polygon.hpp"
#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "ray/coverage.hpp"
#include "transport/uniform/form_factors_analytic.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace rad {

namespace {

ConvexPolygon element_polygon(const ElementTree& tree, const Element& e) {
    ConvexPolygon polygon;
    polygon.count = e.is_triangle() ? 3 : 4;
    for (std::size_t k = 0; k < polygon.count; ++k) polygon.corners[k] = tree.points()[e.corners[k]];
    return polygon;
}

glm::dvec3 corner_mean(const ConvexPolygon& p) {
    glm::dvec3 sum(0.0);
    for (std::size_t k = 0; k < p.count; ++k) sum += p.corners[k];
    return sum / static_cast<double>(p.count);
}

// The point-to-polygon factor over a receiver of n = 3 or 4 corners: at its corners (pulled in a hair, where
// the kernel is finite even at an edge the source touches) and at the points halfway between its centre and
// its corners (where the interpolation between the corners is checked).
struct KernelSamples {
    int n = 4;
    double corner[4] = {};
    double inner[4] = {};

    // The interpolation between corner values v at inner point k.
    double interpolated(const double* v, int k) const {
        if (n == 3) return (4.0 * v[k] + v[(k + 1) % 3] + v[(k + 2) % 3]) / 6.0;
        return (9.0 * v[k] + 3.0 * v[(k + 1) % 4] + 3.0 * v[(k + 3) % 4] + v[(k + 2) % 4]) / 16.0;
    }
};

KernelSamples kernel_samples(const ConvexPolygon& receiver, const glm::dvec3& normal,
                             const ConvexPolygon& source) {
    constexpr double kCornerInset = 1e-3;
    KernelSamples samples;
    samples.n = static_cast<int>(receiver.count);
    const glm::dvec3 centre = corner_mean(receiver);
    auto kernel = [&](const glm::dvec3& x) {
        return std::max(0.0, point_polygon_factor(x, normal, source.span()));
    };
    for (int k = 0; k < samples.n; ++k) {
        samples.inner[k] = kernel(0.5 * (centre + receiver.corners[k]));
        samples.corner[k] = kernel(receiver.corners[k] + kCornerInset * (centre - receiver.corners[k]));
    }
    return samples;
}

// Corner factors whose mean is `mean` and whose differences are the corners': the mean from the more
// accurate rule, the slope from the corners.
void corner_factors(const KernelSamples& k, double mean, double* f) {
    double corner_mean = 0.0;
    for (int c = 0; c < k.n; ++c) corner_mean += k.corner[c] / k.n;
    double sum = 0.0;
    for (int c = 0; c < k.n; ++c) sum += f[c] = std::max(0.0, k.corner[c] - corner_mean + mean);
    const double scale = sum > 0.0 ? mean * k.n / sum : 0.0;
    for (int c = 0; c < k.n; ++c) f[c] *= scale;
    if (k.n == 3) f[3] = mean;  // so the four average to the mean, as HierarchicalLink::mean_factor takes it
}

// The largest gap between the kernel at an inner point and the interpolation of the corner factors there.
double departure(const KernelSamples& k, const double* f) {
    double worst = 0.0;
    for (int c = 0; c < k.n; ++c) worst = std::max(worst, std::abs(k.inner[c] - k.interpolated(f, c)));
    return worst;
}

// Shallower than the analytic estimator's rule: a link whose elements are close gets refined anyway, so its
// quadrature need not resolve the kernel's steepest part as finely.
constexpr AdaptiveRule kLinkRule{0.1, 0.5, 1.0, 3};

}  // namespace

double LinkEstimator::visibility(const ConvexPolygon& from, const glm::dvec3& from_normal,
                                 bool from_partly_covered, const ConvexPolygon& to,
                                 const glm::dvec3& to_normal, bool to_partly_covered, RandomStream& random,
                                 Scratch& s) const {
    const auto count = static_cast<std::size_t>(rays_);
    s.strata.resize(2 * count);
    stratified_square(random, std::span(s.strata).first(count));
    stratified_square(random, std::span(s.strata).last(count));
    s.from.resize(count);
    s.to.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        s.from[k] = point_on_convex_polygon(from.span(), s.strata[k]) + offset_ * from_normal;
        s.to[k] = point_on_convex_polygon(to.span(), s.strata[count + k]) + offset_ * to_normal;
    }
    s.from_covered.assign(count, 0);
    s.to_covered.assign(count, 0);
    if (from_partly_covered) covered_points(s.from, from_normal, scene_, s.from_covered);
    if (to_partly_covered) covered_points(s.to, to_normal, scene_, s.to_covered);
    s.rays.clear();
    for (std::size_t k = 0; k < count; ++k) {
        if (!s.from_covered[k] && !s.to_covered[k])
            s.rays.push_back(Ray{s.from[k], 0.0f, s.to[k] - s.from[k], 1.0f});
    }
    if (s.rays.empty()) return -1.0;
    s.blocked.resize(s.rays.size());
    scene_.occluded(s.rays, s.blocked);
    const auto open = std::count(s.blocked.begin(), s.blocked.end(), std::uint8_t{0});
    return static_cast<double>(open) / static_cast<double>(s.rays.size());
}

double LinkEstimator::exposed_share(std::uint32_t element) const {
    constexpr int kProbes = 64;
    const Element& e = tree_[element];
    const ConvexPolygon polygon = element_polygon(tree_, e);
    return 1.0 - covered_share(polygon.span(), e.shape.normal, scene_, seed_, element, offset_, kProbes);
}

double LinkEstimator::reaching_share(std::uint32_t element, double* escaping) const {
    constexpr auto kRays = static_cast<std::size_t>(kReachingRays);
    thread_local std::vector<glm::dvec2> origins, directions;
    thread_local std::vector<glm::dvec3> points;
    thread_local std::vector<std::uint8_t> covered;
    thread_local std::vector<Ray> rays;
    thread_local std::vector<RayHit> hits;
    const Element& e = tree_[element];
    const double exposed_share = exposed_share_[element];
    if (!(exposed_share > 0.0)) return 0.0;
    const ConvexPolygon polygon = element_polygon(tree_, e);
    RandomStream random(seed_ ^ 0x7265616368ull, element);
    origins.resize(kRays);
    directions.resize(kRays);
    stratified_square(random, origins);
    stratified_square(random, directions);
    points.resize(kRays);
    for (std::size_t k = 0; k < kRays; ++k)
        points[k] = point_on_convex_polygon(polygon.span(), origins[k]) + offset_ * e.shape.normal;
    // From exposed points only: the covered part's share is the exposed_share's to say.
    covered.assign(kRays, 0);
    if (exposed_share < 1.0) covered_points(points, e.shape.normal, scene_, covered);
    const Frame frame = frame_around(e.shape.normal);
    rays.clear();
    for (std::size_t k = 0; k < kRays; ++k)
        if (!covered[k])
            rays.push_back(Ray{points[k], 0.0f, frame.to_world(cosine_direction(directions[k])), 1e30f});
    if (rays.empty()) return -1.0;
    hits.resize(rays.size());
    scene_.intersect(rays, hits);
    const auto reached =
        std::count_if(hits.begin(), hits.end(), [](const RayHit& h) { return h.patch < RayHit::kBackFace; });
    if (escaping) {
        const auto missed = std::count_if(hits.begin(), hits.end(),
                                          [](const RayHit& h) { return h.patch == RayHit::kMissed; });
        *escaping = static_cast<double>(missed) / static_cast<double>(rays.size());
    }
    return std::min(1.0, exposed_share) * static_cast<double>(reached) / static_cast<double>(rays.size());
}

LinkEstimate LinkEstimator::operator()(std::uint32_t r, std::uint32_t s, Scratch& scratch, int draw) const {
    LinkEstimate estimate;
    if (r == s) return estimate;
    const Element& receiver = tree_[r];
    const Element& source = tree_[s];
    const ConvexPolygon whole_receiver = element_polygon(tree_, receiver);
    const ConvexPolygon seen_source =
        clip_to_front(element_polygon(tree_, source), receiver.shape.centroid, receiver.shape.normal);
    if (seen_source.empty()) return estimate;
    const ConvexPolygon facing_receiver =
        clip_to_front(whole_receiver, source.shape.centroid, source.shape.normal);
    if (facing_receiver.empty()) return estimate;
    if (!(polygon_area(facing_receiver.span()) > 0.0) || !(polygon_area(seen_source.span()) > 0.0))
        return estimate;
    const KernelSamples kernel = kernel_samples(whole_receiver, receiver.shape.normal, seen_source);
    // The mean by adaptive quadrature (as the analytic estimator has it: to 0.2 % even for elements that
    // share an edge, where the kernel is steepest); the corners give only the slope.
    const double unoccluded =
        unoccluded_form_factor(facing_receiver, receiver.shape.centroid, receiver.shape.normal,
                               receiver.shape.area, seen_source, source.shape.normal, kLinkRule);
    if (!(unoccluded > 0.0)) return estimate;
    const double receiver_exposed = exposed_share_[r], source_exposed = exposed_share_[s];
    if (!(receiver_exposed > 0.0) || !(source_exposed > 0.0)) return estimate;  // wholly covered
    const bool receiver_partly = receiver_exposed < 1.0, source_partly = source_exposed < 1.0;
    estimate.facing = true;
    RandomStream random(seed_ + static_cast<std::uint64_t>(draw) * 0x9e3779b97f4a7c15ull, std::min(r, s),
                        std::max(r, s));
    // The visibility between the exposed parts, with rays that always run from the lower index to the
    // higher, so both directions of a pair see the same.
    const double visible = r < s
                               ? visibility(facing_receiver, receiver.shape.normal, receiver_partly,
                                            seen_source, source.shape.normal, source_partly, random, scratch)
                               : visibility(seen_source, source.shape.normal, source_partly, facing_receiver,
                                            receiver.shape.normal, receiver_partly, random, scratch);
    if (!(visible > 0.0)) return estimate;
    // The irradiance is a mean over the whole receiver, its covered part dark (× its exposed_share), and
    // comes from the exposed part of the source, whose radiosity is B_source / its exposed_share.
    const double exposed_scale = std::min(1.0, receiver_exposed) / source_exposed;
    double factor[4] = {0.0, 0.0, 0.0, 0.0};
    corner_factors(kernel, unoccluded, factor);
    estimate.transports = true;
    for (int c = 0; c < 4; ++c) estimate.factor[c] = static_cast<float>(factor[c] * visible * exposed_scale);
    estimate.uncertainty = static_cast<float>(
        (departure(kernel, factor) * visible + 2.0 * unoccluded * std::min(visible, 1.0 - visible)) *
        exposed_scale);
    return estimate;
}

}  // namespace rad
