#include "transport/pooled_reach.hpp"

#include <algorithm>
#include <vector>

namespace rad {

// f(r) = Σ A min(cap, r links) is continuous, rises with r, and is linear between the ratios cap / links at
// which one leaf after another reaches its cap: walk those in order until f passes the measured sum, then
// solve the piece it passes on.
double pooled_ratio(std::span<const PoolLeaf> pool) {
    struct Cap {
        double at = 0.0, area = 0.0, links = 0.0, cap = 0.0;
    };
    std::vector<Cap> caps;
    caps.reserve(pool.size());
    double measured = 0.0, slope = 0.0;
    for (const PoolLeaf& leaf : pool) {
        measured += leaf.area * leaf.measured;
        if (!(leaf.links > 0.0)) continue;  // no links: its prior is 0 whatever the ratio
        caps.push_back({leaf.cap / leaf.links, leaf.area, leaf.links, leaf.cap});
        slope += leaf.area * leaf.links;
    }
    if (!(slope > 0.0)) return 1.0;
    std::sort(caps.begin(), caps.end(), [](const Cap& a, const Cap& b) { return a.at < b.at; });
    double capped = 0.0;  // Σ A cap of the leaves at their cap
    for (const Cap& c : caps) {
        if (!(slope > 0.0) || capped + c.at * slope >= measured)
            return slope > 0.0 ? std::max(0.0, measured - capped) / slope : c.at;
        capped += c.area * c.cap;
        slope -= c.area * c.links;
    }
    return caps.back().at;  // every prior at its cap and still short of the measurement
}

}  // namespace rad
