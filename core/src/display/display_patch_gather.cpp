#include "display/display_patch_gather.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "display/gather_rows.hpp"
#include "ray/ray_offset.hpp"
#include "sampling/hemisphere_rays.hpp"

namespace rad {

namespace {

// A key of the patch gather's random streams, apart from every other pass's.
constexpr std::uint64_t kPatchGatherKey = 0x6a7e'f17a'1000'0002ull;
// A display patch covered all but this share keeps its rays' plain mean: it is hidden, and the division
// would only amplify its noise.
constexpr double kFewestExposed = 0.05;

struct Scratch {
    std::vector<Ray> rays;
    std::vector<double> weights;
    std::vector<RayHit> hits;
    std::vector<std::pair<std::uint32_t, double>> met;
};

void gather_row(const DisplayPatchGatherTraceInput& input, std::uint32_t d, int count, double offset,
                Scratch& s, GatherRow& row) {
    s.rays.resize(static_cast<std::size_t>(count));
    s.weights.resize(s.rays.size());
    s.hits.resize(s.rays.size());
    hemisphere_rays(*input.patches, d, input.seed ^ kPatchGatherKey, offset, s.rays, s.weights);
    input.solution_rays->intersect(s.rays, s.hits);
    s.met.clear();
    for (std::size_t k = 0; k < s.hits.size(); ++k) {
        const std::uint32_t q = s.hits[k].patch;
        if (q != RayHit::kMissed && q != RayHit::kBackFace) s.met.emplace_back(q, s.weights[k]);
    }
    std::sort(s.met.begin(), s.met.end());
    const double exposed = input.exposed[d] > kFewestExposed ? std::min(1.0, input.exposed[d]) : 1.0;
    const double each = 1.0 / (count * exposed);
    for (std::size_t k = 0; k < s.met.size(); ++k) {
        const float w = static_cast<float>(each * s.met[k].second);
        if (k > 0 && s.met[k].first == s.met[k - 1].first) {
            row.weight.back() += w;
            continue;
        }
        row.patch.push_back(s.met[k].first);
        row.weight.push_back(w);
    }
}

// Whether `input.traced` is a table for these display patches over these solution patches.
bool takes_traced(const DisplayPatchGatherTraceInput& input, std::size_t n) {
    const GatherTable* t = input.traced;
    if (!t || t->row_begin.size() != n + 1 || t->row_begin.front() != 0 ||
        t->row_begin.back() != t->patch.size() || t->weight.size() != t->patch.size())
        return false;
    return std::all_of(t->patch.begin(), t->patch.end(),
                       [&](std::uint32_t q) { return q < input.solution->size(); });
}

}  // namespace

void trace_display_patch_gather(DisplayMesh& display, const DisplayPatchGatherTraceInput& input) {
    const PatchMesh& patches = *input.patches;
    const std::size_t n = patches.size();
    if (input.exposed.size() != n || display.patch_count != n) {
        throw std::invalid_argument("trace_display_patch_gather: the arrays do not have one entry per patch");
    }
    display.traced.patch_gather = {};
    display.light.patch_gather = {};
    if (n == 0) return;
    if (takes_traced(input, n)) {
        display.traced.patch_gather = *input.traced;
        return;
    }
    const int count = static_cast<int>(std::min<std::size_t>(kPatchGatherRays, input.ray_budget / n));
    if (count < kPatchGatherMinRays) return;
    Progress* progress = input.progress;
    if (progress) {
        progress->begin("final gather at the display's patches", n);
        progress->note(std::to_string(n) + " patches x " + std::to_string(count) + " rays");
    }
    const double offset = ray_offset(patches);
    std::vector<GatherRow> rows(n);
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, 16), [&](const tbb::blocked_range<std::size_t>& r) {
            Scratch scratch;
            if (progress && progress->cancelled()) throw Cancelled{};
            for (std::size_t d = r.begin(); d != r.end(); ++d)
                gather_row(input, static_cast<std::uint32_t>(d), count, offset, scratch, rows[d]);
            if (progress) progress->advance(r.size());
        });
    append_rows(rows, display.traced.patch_gather);
}

void light_display_patch_gather(DisplayMesh& display, const DisplayPatchGatherArrays& arrays) {
    if (arrays.emission.size() != display.patch_count || arrays.reflectance.size() != display.patch_count ||
        arrays.source.size() != display.solution_patch_count()) {
        throw std::invalid_argument("light_display_patch_gather: the arrays do not have one entry per patch");
    }
    DisplayLight::PatchGather& gather = display.light.patch_gather;
    gather = {};
    if (display.traced.patch_gather.empty()) return;
    gather.emission.assign(arrays.emission.begin(), arrays.emission.end());
    gather.reflectance.assign(arrays.reflectance.begin(), arrays.reflectance.end());
    gather.source.assign(arrays.source.begin(), arrays.source.end());
}

}  // namespace rad
