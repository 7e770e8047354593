#include "sampling/power_draws.hpp"

#include <algorithm>
#include <cmath>

namespace rad {

bool draw_by_power(const std::vector<double>& weight, double total, int draws, double offset,
                   std::vector<PowerDraw>& out) {
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
    // Rounding in the running sum can leave the last point just past the end: it is the last source's.
    if (drawn < draws) {
        if (out.empty() || out.back().source != last) out.push_back({static_cast<std::uint32_t>(last), 0});
        out.back().count += static_cast<std::uint32_t>(draws - drawn);
    }
    return false;
}

double power_draw_ray_scale(std::size_t rays, double expected_draws, bool every_source) {
    const double chance = every_source ? 1.0 : std::min(1.0, expected_draws);
    return 1.0 / (static_cast<double>(rays) * chance);
}

}  // namespace rad
