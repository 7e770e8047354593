#include <algorithm>
#include <numeric>

#include "transport/adaptive/adaptive_shadow.hpp"

namespace rad {

std::vector<ShadowSource> shadow_sources(const SolvedLeaves& leaves) {
    const std::size_t bases = leaves.tree.base_size();
    std::vector<double> power(bases, 0.0), area(bases, 0.0);
    double total = 0.0;
    for (std::size_t i = 0; i < leaves.radiosity.size(); ++i) {
        const double p = leaves.system.area[i] * luminance(leaves.radiosity[i]);
        power[leaves.base_patch(i)] += p;
        area[leaves.base_patch(i)] += leaves.system.area[i];
        total += p;
    }
    std::vector<std::uint32_t> order(bases);
    std::iota(order.begin(), order.end(), 0u);
    // Ties keep base order, so the choice does not depend on the sort's implementation.
    std::stable_sort(order.begin(), order.end(),
                     [&power](std::uint32_t a, std::uint32_t b) { return power[a] > power[b]; });
    std::vector<ShadowSource> sources;
    double taken = 0.0;
    for (const std::uint32_t b : order) {
        if (sources.size() >= kMaxShadowSources || taken >= kSourcePowerShare * total || !(power[b] > 0.0))
            break;
        sources.push_back({b, power[b] / area[b]});
        taken += power[b];
    }
    return sources;
}

}  // namespace rad
