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
