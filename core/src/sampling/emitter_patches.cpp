#include "sampling/emitter_patches.hpp"

#include <algorithm>

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

bool sample_emitter_columns(const PatchMesh& patches, std::span<const std::uint32_t> emitters) {
    if (emitters.empty() || emitters.size() > kMaxSampledEmitterPatches) return false;
    double total = 0.0, emitting = 0.0;
    for (const Patch& p : patches.patches) total += p.area;
    for (std::uint32_t e : emitters) emitting += patches.patches[e].area;
    return emitting <= kMaxEmitterAreaShare * total;
}

}  // namespace rad
