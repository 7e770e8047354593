#include "transport/uniform/form_factors_hemisphere.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <vector>

#include "ray/coverage.hpp"
#include "sampling/bilinear_quad.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

// Rays traced per Embree call while a row is computed: large enough for Embree's stream interface, small
// enough that the buffers stay in cache.
constexpr std::size_t kBatchRays = 256;

// Per-thread working memory: the rays of one batch and a dense accumulator over all patches, with the list
// of patches touched so that clearing it costs as much as filling it.
struct HemisphereScratch {
    std::vector<Ray> rays;
    std::vector<double> weights;
    std::vector<RayHit> hits;
    std::vector<double> accumulated;
    std::vector<std::uint32_t> touched;
};

}  // namespace

double ray_offset(const PatchMesh& patches) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : patches.points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    if (patches.points.empty()) return 0.0;
    const glm::dvec3 magnitude = glm::max(glm::abs(lo), glm::abs(hi));
    const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    return std::max(kRayOffsetFraction * glm::length(hi - lo),
                    kRayOffsetUlps * std::numeric_limits<float>::epsilon() * largest);
}

void hemisphere_rays(const PatchMesh& patches, std::uint32_t patch, std::uint64_t seed, double offset,
                     std::span<Ray> rays, std::span<double> weights) {
    RandomStream random(seed, patch);
    // Reused from call to call: a pass calls this once per patch on each thread.
    thread_local std::vector<glm::dvec2> origins, directions;
    origins.resize(rays.size());
    directions.resize(rays.size());
    stratified_square(random, origins);
    // Directions stay in stratum order (the origins' shuffle pairs them at random), so consecutive rays run
    // in similar directions, which Embree traces a little faster.
    stratified_square(random, directions, false);

    const glm::uvec4& c = patches.corners[patch];
    const Patch& p = patches.patches[patch];
    const BilinearQuad quad{patches.points[c[0]], patches.points[c[1]], patches.points[c[2]],
                            patches.points[c[3]]};
    const bool triangle = patches.is_triangle(patch);
    const Frame frame = frame_around(p.normal);
    const glm::dvec3 lift = offset * p.normal;
    for (std::size_t k = 0; k < rays.size(); ++k) {
        glm::dvec3 origin;
        if (triangle) {
            origin = point_on_triangle(quad.a, quad.b, quad.c, origins[k]);
            weights[k] = 1.0;
        } else {
            origin = quad.point(origins[k]);
            weights[k] = quad.jacobian(origins[k]) / p.area;
        }
        rays[k].origin = origin + lift;
        rays[k].tnear = 0.0f;
        rays[k].direction = frame.to_world(cosine_direction(directions[k]));
        rays[k].tfar = std::numeric_limits<float>::infinity();
    }
}

RowFunction hemisphere_rows(const PatchMesh& patches, const RayScene& scene, int rays, std::uint64_t seed,
                            std::vector<double>& covered, std::vector<double>& escaped,
                            std::vector<std::uint8_t> skipped) {
    const double offset = ray_offset(patches);
    auto scratch = std::make_shared<tbb::enumerable_thread_specific<HemisphereScratch>>([&patches, rays] {
        HemisphereScratch s;
        s.rays.resize(static_cast<std::size_t>(rays));
        s.weights.resize(static_cast<std::size_t>(rays));
        s.hits.resize(kBatchRays);
        s.accumulated.assign(patches.size(), 0.0);
        return s;
    });
    skipped.resize(patches.size(), 0);
    return [&patches, &scene, seed, offset, scratch, &covered, &escaped, skipped = std::move(skipped)](
               std::uint32_t i, std::vector<RowEntry>& entries, RowStats& stats) {
        HemisphereScratch& s = scratch->local();
        hemisphere_rays(patches, i, seed, offset, s.rays, s.weights);
        double blocked = 0.0;  // each row is computed once, so covered[i] and escaped[i] have one writer
        double missed = 0.0;
        for (std::size_t first = 0; first < s.rays.size(); first += kBatchRays) {
            const std::size_t count = std::min(kBatchRays, s.rays.size() - first);
            scene.intersect(std::span(s.rays).subspan(first, count), s.hits);
            for (std::size_t k = 0; k < count; ++k) {
                const std::uint32_t j = s.hits[k].patch;
                if (j == RayHit::kMissed) ++stats.escaped_rays;
                const double weight = s.weights[first + k];
                if (j == RayHit::kBackFace) blocked += weight;
                if (j == RayHit::kMissed) missed += weight;
                if (j >= patches.size() || j == i || !(weight > 0.0)) continue;  // escaped or blocked
                if (skipped[j]) continue;
                if (s.accumulated[j] == 0.0) s.touched.push_back(j);
                s.accumulated[j] += weight;
            }
        }
        stats.rays += s.rays.size();
        stats.hemisphere_rays += s.rays.size();
        std::sort(s.touched.begin(), s.touched.end());
        const double scale = 1.0 / static_cast<double>(s.rays.size());
        // Rays that met back faces came from covered points or passed under a single-sided sheet; probes
        // tell.
        covered[i] = blocked > 0.0 ? covered_share(patches, scene, i, seed, offset) : 0.0;
        escaped[i] = missed * scale;
        for (std::uint32_t j : s.touched) {
            entries.push_back({j, s.accumulated[j] * scale});
            s.accumulated[j] = 0.0;
        }
        s.touched.clear();
    };
}

}  // namespace rad
