#include "ray/coverage.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "ray/ray_offset.hpp"
#include "sampling/hemisphere_rays.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

constexpr int kDirections = 5;              // the normal and four grazing azimuths
constexpr double kGrazingElevation = 10.0;  // degrees above the patch's plane
constexpr std::uint64_t kProbeSalt = 0x636f766572656421ull;

// The probe directions in the patch's frame: +z, then four around it at the grazing elevation.
std::array<glm::dvec3, kDirections> probe_directions() {
    const double elevation = kGrazingElevation * std::numbers::pi / 180.0;
    std::array<glm::dvec3, kDirections> directions{glm::dvec3(0, 0, 1)};
    for (int k = 0; k < 4; ++k) {
        const double azimuth = k * std::numbers::pi / 2.0;
        directions[k + 1] = {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                             std::sin(elevation)};
    }
    return directions;
}

// The weighted share of origins whose probes (kDirections per origin, in order) all met back faces.
double covered_weight(std::span<const RayHit> hits, std::span<const double> weights) {
    const std::size_t origins = weights.size();
    double covered = 0.0, total = 0.0;
    for (std::size_t k = 0; k < origins; ++k) {
        bool inside = true;
        for (int d = 0; d < kDirections && inside; ++d)
            inside = hits[k * kDirections + d].patch == RayHit::kBackFace;
        total += weights[k];
        if (inside) covered += weights[k];
    }
    return total > 0.0 ? covered / total : 0.0;
}

}  // namespace

double covered_share(const PatchMesh& patches, const RayScene& scene, std::uint32_t patch, std::uint64_t seed,
                     double offset) {
    // The hemisphere estimator's own origins and area weights, from a stream of their own.
    thread_local std::vector<Ray> origins, probes;
    thread_local std::vector<double> weights;
    thread_local std::vector<RayHit> hits;
    origins.resize(kCoverageProbes);
    weights.resize(kCoverageProbes);
    hemisphere_rays(patches, patch, seed ^ kProbeSalt, offset, origins, weights);

    const Frame frame = frame_around(patches.patches[patch].normal);
    const std::array<glm::dvec3, kDirections> local = probe_directions();
    probes.resize(origins.size() * kDirections);
    hits.resize(probes.size());
    for (std::size_t k = 0; k < origins.size(); ++k) {
        for (int d = 0; d < kDirections; ++d) {
            Ray& probe = probes[k * kDirections + d];
            probe = origins[k];
            probe.direction = frame.to_world(local[d]);
        }
    }
    scene.intersect(probes, hits);
    return covered_weight(hits, weights);
}

void covered_points(std::span<const glm::dvec3> points, const glm::dvec3& normal, const RayScene& scene,
                    std::vector<std::uint8_t>& covered) {
    thread_local std::vector<Ray> probes;
    thread_local std::vector<RayHit> hits;
    const Frame frame = frame_around(normal);
    const std::array<glm::dvec3, kDirections> local = probe_directions();
    probes.resize(points.size() * kDirections);
    hits.resize(probes.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        for (int d = 0; d < kDirections; ++d)
            probes[k * kDirections + d] = Ray{points[k], 0.0f, frame.to_world(local[d]), 1e30f};
    }
    scene.intersect(probes, hits);
    covered.resize(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        bool inside = true;
        for (int d = 0; d < kDirections && inside; ++d)
            inside = hits[k * kDirections + d].patch == RayHit::kBackFace;
        covered[k] = inside ? 1 : 0;
    }
}

double covered_share(std::span<const glm::dvec3> polygon, const glm::dvec3& normal, const RayScene& scene,
                     std::uint64_t seed, std::uint64_t key, double offset, int count) {
    thread_local std::vector<glm::dvec2> strata;
    thread_local std::vector<glm::dvec3> points;
    thread_local std::vector<std::uint8_t> covered;
    strata.resize(static_cast<std::size_t>(count));
    RandomStream random(seed ^ kProbeSalt, key);
    stratified_square(random, strata, false);
    points.resize(strata.size());
    for (std::size_t k = 0; k < strata.size(); ++k)
        points[k] = point_on_convex_polygon(polygon, strata[k]) + offset * normal;
    covered_points(points, normal, scene, covered);
    const auto inside = std::count(covered.begin(), covered.end(), std::uint8_t{1});
    return strata.empty() ? 0.0 : static_cast<double>(inside) / static_cast<double>(strata.size());
}

void measure_coverage(const PatchMesh& patches, const RayScene& scene, std::uint64_t seed,
                      std::vector<double>& covered) {
    const double offset = ray_offset(patches);
    tbb::parallel_for(std::size_t(0), patches.size(), [&](std::size_t i) {
        covered[i] = covered_share(patches, scene, static_cast<std::uint32_t>(i), seed, offset);
    });
}

}  // namespace rad
