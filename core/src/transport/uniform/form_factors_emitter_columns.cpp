#include "transport/uniform/form_factors_emitter_columns.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <memory>

#include "sampling/patch_shapes.hpp"
#include "sampling/power_draws.hpp"
#include "transport/uniform/form_factors_analytic.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"

namespace rad {

namespace {

// A key of the emitter rows' random streams of their own (draws and rays), apart from every other pass's.
constexpr std::uint64_t kDrawKey = 0xd4a3'11e5'0000'0001ull;

struct Candidate {
    std::uint32_t column;
    double unoccluded;
    double scale;  // what one open shadow ray adds, over U_ij
    std::size_t first_ray, rays;
};

struct EmitterScratch {
    std::vector<double> weight;
    std::vector<PowerDraw> draws;
    std::vector<Candidate> candidates;
    std::vector<Ray> rays;
    std::vector<std::uint8_t> blocked;
    std::vector<glm::dvec2> strata;
};

}  // namespace

std::vector<std::uint8_t> column_flags(std::size_t patch_count, std::span<const std::uint32_t> columns) {
    std::vector<std::uint8_t> flags(patch_count, 0);
    for (std::uint32_t c : columns) flags[c] = 1;
    return flags;
}

RowFunction emitter_rows(const PatchMesh& patches, const RayScene& scene, std::vector<std::uint32_t> emitters,
                         std::vector<double> luminance, int hemisphere_rays, std::uint64_t seed) {
    std::vector<PatchShape> shapes = patch_shapes(patches);
    EmitterSet set;
    set.shapes.reserve(emitters.size());
    for (std::uint32_t j : emitters) set.shapes.push_back(shapes[j]);
    set.columns = std::move(emitters);
    set.luminance = std::move(luminance);
    return emitter_rows(std::move(shapes), {}, std::move(set), scene, ray_offset(patches), hemisphere_rays,
                        seed);
}

RowFunction emitter_rows(std::vector<PatchShape> receivers, std::vector<std::uint32_t> own_column,
                         EmitterSet emitters, const RayScene& scene, double offset, int hemisphere_rays,
                         std::uint64_t seed) {
    auto shapes = std::make_shared<const std::vector<PatchShape>>(std::move(receivers));
    auto own = std::make_shared<const std::vector<std::uint32_t>>(std::move(own_column));
    auto set = std::make_shared<const EmitterSet>(std::move(emitters));
    auto scratch = std::make_shared<tbb::enumerable_thread_specific<EmitterScratch>>();
    const std::size_t count = set->columns.size();
    const std::size_t budget = std::min<std::size_t>(
        static_cast<std::size_t>(std::max(hemisphere_rays, kEmitterShadowRays)), kEmitterShadowRays * count);
    const int draws = static_cast<int>(std::max<std::size_t>(1, budget / kRaysPerDraw));
    return [&scene, shapes, own, set, scratch, offset, draws, seed](
               std::uint32_t i, std::vector<RowEntry>& entries, RowStats& stats) {
        EmitterScratch& s = scratch->local();
        const PatchShape& pi = (*shapes)[i];
        const std::uint32_t skip = own->empty() ? i : (*own)[i];
        const std::size_t n = set->columns.size();
        s.weight.assign(n, 0.0);
        double total = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            if (set->columns[k] == skip) continue;
            s.weight[k] =
                set->luminance[k] * factor_weight(pi.centroid, pi.normal, pi.radius, set->shapes[k]);
            total += s.weight[k];
        }
        if (!(total > 0.0)) return;
        RandomStream draw_random(seed ^ kDrawKey, i);
        const bool every_emitter = draw_by_power(s.weight, total, draws, draw_random.uniform(), s.draws);
        s.candidates.clear();
        s.rays.clear();
        for (const PowerDraw& d : s.draws) {
            const std::uint32_t j = set->columns[d.source];
            const PatchShape& pj = set->shapes[d.source];
            const ConvexPolygon source = clip_to_front(pj.polygon, pi.centroid, pi.normal);
            if (source.empty()) continue;
            const ConvexPolygon receiver = clip_to_front(pi.polygon, pj.centroid, pj.normal);
            if (receiver.empty()) continue;
            const double unoccluded =
                unoccluded_form_factor(receiver, pi.centroid, pi.normal, pi.area, source, pj.normal);
            if (!(unoccluded > 0.0)) continue;
            const std::size_t rays = static_cast<std::size_t>(kRaysPerDraw) * d.count;
            const double expected = draws * s.weight[d.source] / total;
            s.candidates.push_back(
                {j, unoccluded, power_draw_ray_scale(rays, expected, every_emitter), s.rays.size(), rays});
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
