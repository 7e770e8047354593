#include "transport/uniform/form_factors_emitter_columns.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <memory>

namespace rad {

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

int emitter_shadow_rays(std::size_t emitter_patches, int hemisphere_rays) {
    if (emitter_patches == 0) return 0;
    const auto share = static_cast<std::size_t>(hemisphere_rays) / emitter_patches;
    const auto rays = static_cast<int>(std::min<std::size_t>(share, kEmitterShadowRays));
    return rays >= kMinEmitterShadowRays ? rays : 0;
}

std::vector<std::uint8_t> column_flags(std::size_t patch_count, std::span<const std::uint32_t> columns) {
    std::vector<std::uint8_t> flags(patch_count, 0);
    for (std::uint32_t c : columns) flags[c] = 1;
    return flags;
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
