#include "transport/uniform/form_factors_emitter_columns.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <memory>
#include <numbers>

#include "transport/uniform/form_factors_analytic.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"
#include "transport/uniform/patch_shapes.hpp"

namespace rad {

namespace {

// A key of the emitter rows' random streams of their own (draws and rays), apart from every other pass's.
constexpr std::uint64_t kDrawKey = 0xd4a3'11e5'0000'0001ull;

// A weight roughly proportional to the factor from receiver i to emitter j, and positive wherever the exact
// one can be: the disk approximation A_j c_i c_j / (π g² + A_j) with each cosine lifted by the patches'
// extent over their gap g, so a neighbour at a grazing angle is never dismissed.
double factor_weight(const PatchShape& i, const PatchShape& j) {
    const glm::dvec3 d = j.centroid - i.centroid;
    const double distance = glm::length(d);
    if (!(distance > 0.0)) return 0.0;
    const glm::dvec3 towards = d / distance;
    const double gap = std::max(0.0, distance - i.radius - j.radius);
    const double lift = gap > 0.0 ? (i.radius + j.radius) / gap : 1.0;
    const double ci = std::clamp(glm::dot(i.normal, towards) + lift, 0.0, 1.0);
    const double cj = std::clamp(-glm::dot(j.normal, towards) + lift, 0.0, 1.0);
    return j.area * ci * cj / (std::numbers::pi * gap * gap + j.area);
}

struct Draw {
    std::uint32_t emitter;  // position in the emitter list
    std::uint32_t count;
};

struct Candidate {
    std::uint32_t column;
    double unoccluded;
    double scale;  // what one open shadow ray adds, over U_ij
    std::size_t first_ray, rays;
};

struct EmitterScratch {
    std::vector<double> weight;
    std::vector<Draw> draws;
    std::vector<Candidate> candidates;
    std::vector<Ray> rays;
    std::vector<std::uint8_t> blocked;
    std::vector<glm::dvec2> strata;
};

// The emitters a row aims at, and how often. When no more emitters can send light than there are draws,
// each of them is drawn, about in proportion to its weight (at least once); else `draws` points evenly spaced
// from a random offset along the weights' running sum (systematic sampling), so an emitter of weight share p
// is drawn floor(K p) or ceil(K p) times, and one with K p < 1 once with probability K p. Returns whether
// every emitter was drawn.
bool draw_emitters(const std::vector<double>& weight, double total, int draws, double offset,
                   std::vector<Draw>& out) {
    out.clear();
    const auto active = static_cast<std::size_t>(
        std::count_if(weight.begin(), weight.end(), [](double w) { return w > 0.0; }));
    if (active <= static_cast<std::size_t>(draws)) {
        for (std::size_t k = 0; k < weight.size(); ++k) {
            if (!(weight[k] > 0.0)) continue;
            const double expected = draws * weight[k] / total;
            out.push_back({static_cast<std::uint32_t>(k),
                           static_cast<std::uint32_t>(std::max(1.0, std::round(expected)))});
        }
        return true;
    }
    const double step = total / draws;
    double next = offset * step, running = 0.0;
    int drawn = 0;
    std::size_t last = 0;
    for (std::size_t k = 0; k < weight.size() && drawn < draws; ++k) {
        if (!(weight[k] > 0.0)) continue;
        last = k;
        running += weight[k];
        std::uint32_t count = 0;
        while (drawn < draws && next < running) {
            ++count;
            ++drawn;
            next += step;
        }
        if (count > 0) out.push_back({static_cast<std::uint32_t>(k), count});
    }
    // Rounding in the running sum can leave the last point just past the end: it is the last emitter's.
    if (drawn < draws) {
        if (out.empty() || out.back().emitter != last) out.push_back({static_cast<std::uint32_t>(last), 0});
        out.back().count += static_cast<std::uint32_t>(draws - drawn);
    }
    return false;
}

// What one of an emitter's open shadow rays adds to U_ij: 1 / rays when every emitter that can send light
// is drawn (or when this one always is, K p ≥ 1), the visible share; else 1 / (rays · K p), which counts the
// rows that do not draw it.
double ray_scale(std::size_t rays, double expected_draws, bool every_emitter) {
    const double chance = every_emitter ? 1.0 : std::min(1.0, expected_draws);
    return 1.0 / (static_cast<double>(rays) * chance);
}

}  // namespace

std::vector<std::uint32_t> emitting_patches(const PatchMesh& patches,
                                            std::span<const std::uint32_t> emitting_surfaces) {
    std::uint32_t surfaces = 0;
    for (const Patch& p : patches.patches) surfaces = std::max(surfaces, p.surface + 1);
    std::vector<std::uint8_t> emits(surfaces, 0);
    for (std::uint32_t s : emitting_surfaces) {
        if (s < surfaces) emits[s] = 1;
    }
    std::vector<std::uint32_t> columns;
    for (std::uint32_t p = 0; p < patches.size(); ++p) {
        if (emits[patches.patches[p].surface]) columns.push_back(p);
    }
    return columns;
}

bool sample_emitter_columns(const PatchMesh& patches, std::span<const std::uint32_t> emitters) {
    if (emitters.empty() || emitters.size() > kMaxSampledEmitterPatches) return false;
    double total = 0.0, emitting = 0.0;
    for (const Patch& p : patches.patches) total += p.area;
    for (std::uint32_t e : emitters) emitting += patches.patches[e].area;
    return emitting <= kMaxEmitterAreaShare * total;
}

std::vector<std::uint8_t> column_flags(std::size_t patch_count, std::span<const std::uint32_t> columns) {
    std::vector<std::uint8_t> flags(patch_count, 0);
    for (std::uint32_t c : columns) flags[c] = 1;
    return flags;
}

RowFunction emitter_rows(const PatchMesh& patches, const RayScene& scene, std::vector<std::uint32_t> emitters,
                         std::vector<double> luminance, int hemisphere_rays, std::uint64_t seed) {
    auto shapes = std::make_shared<const std::vector<PatchShape>>(patch_shapes(patches));
    auto list = std::make_shared<const std::vector<std::uint32_t>>(std::move(emitters));
    auto power = std::make_shared<const std::vector<double>>(std::move(luminance));
    auto scratch = std::make_shared<tbb::enumerable_thread_specific<EmitterScratch>>();
    const double offset = ray_offset(patches);
    const std::size_t budget =
        std::min<std::size_t>(static_cast<std::size_t>(std::max(hemisphere_rays, kEmitterShadowRays)),
                              kEmitterShadowRays * list->size());
    const int draws = static_cast<int>(std::max<std::size_t>(1, budget / kRaysPerDraw));
    return [&scene, shapes, list, power, scratch, offset, draws, seed](
               std::uint32_t i, std::vector<RowEntry>& entries, RowStats& stats) {
        const std::vector<PatchShape>& shape = *shapes;
        EmitterScratch& s = scratch->local();
        const PatchShape& pi = shape[i];
        s.weight.assign(list->size(), 0.0);
        double total = 0.0;
        for (std::size_t k = 0; k < list->size(); ++k) {
            const std::uint32_t j = (*list)[k];
            if (j == i) continue;
            s.weight[k] = (*power)[k] * factor_weight(pi, shape[j]);
            total += s.weight[k];
        }
        if (!(total > 0.0)) return;
        RandomStream draw_random(seed ^ kDrawKey, i);
        const bool every_emitter = draw_emitters(s.weight, total, draws, draw_random.uniform(), s.draws);
        s.candidates.clear();
        s.rays.clear();
        for (const Draw& d : s.draws) {
            const std::uint32_t j = (*list)[d.emitter];
            const PatchShape& pj = shape[j];
            const ConvexPolygon source = clip_to_front(pj.polygon, pi.centroid, pi.normal);
            if (source.empty()) continue;
            const ConvexPolygon receiver = clip_to_front(pi.polygon, pj.centroid, pj.normal);
            if (receiver.empty()) continue;
            const double unoccluded =
                unoccluded_form_factor(receiver, pi.centroid, pi.normal, pi.area, source, pj.normal);
            if (!(unoccluded > 0.0)) continue;
            const std::size_t rays = static_cast<std::size_t>(kRaysPerDraw) * d.count;
            const double expected = draws * s.weight[d.emitter] / total;
            s.candidates.push_back(
                {j, unoccluded, ray_scale(rays, expected, every_emitter), s.rays.size(), rays});
            s.strata.resize(2 * rays);
            RandomStream random(seed ^ kDrawKey, i, j);
            append_shadow_rays(receiver, pi.normal, source, pj.normal, random, offset, s.strata, s.rays);
        }
        s.blocked.resize(s.rays.size());
        scene.occluded(s.rays, s.blocked);
        stats.rays += s.rays.size();
        for (const Candidate& c : s.candidates) {
            const auto first = s.blocked.begin() + static_cast<std::ptrdiff_t>(c.first_ray);
            const auto open = std::count(first, first + static_cast<std::ptrdiff_t>(c.rays), std::uint8_t{0});
            if (open > 0) entries.push_back({c.column, c.unoccluded * static_cast<double>(open) * c.scale});
        }
        // The draws follow the emitter list, which is sorted: the entries are in column order.
    };
}

RowFunction merged_rows(RowFunction first, RowFunction second) {
    auto scratch = std::make_shared<tbb::enumerable_thread_specific<std::vector<RowEntry>>>();
    return [first = std::move(first), second = std::move(second), scratch](
               std::uint32_t i, std::vector<RowEntry>& entries, RowStats& stats) {
        first(i, entries, stats);
        std::vector<RowEntry>& more = scratch->local();
        more.clear();
        second(i, more, stats);
        const auto middle = static_cast<std::ptrdiff_t>(entries.size());
        entries.insert(entries.end(), more.begin(), more.end());
        std::inplace_merge(entries.begin(), entries.begin() + middle, entries.end(),
                           [](const RowEntry& a, const RowEntry& b) { return a.column < b.column; });
    };
}

}  // namespace rad
