#include "bench/path_tracer_search.hpp"

#include <algorithm>
#include <cmath>

namespace rad {

namespace {

// log spp at `target`, on the line through (log error, log spp) of the two samples.
double interpolated_spp(const PathTracerSample& above, const PathTracerSample& reached, double target) {
    const double e0 = std::log(above.error), e1 = std::log(reached.error);
    if (!(e0 > e1) || !(target > 0.0)) return reached.spp;
    const double t = std::clamp((e0 - std::log(target)) / (e0 - e1), 0.0, 1.0);
    return std::exp(std::log(above.spp) + t * (std::log(reached.spp) - std::log(above.spp)));
}

}  // namespace

PathTracerSearch find_path_tracer_spp(const std::function<PathTracerSample(int spp)>& measure, double target,
                                      int start, int max_spp) {
    PathTracerSearch search;
    PathTracerSample sample = measure(std::max(1, start));
    if (sample.error <= target) {
        search.found = true;
        search.reached = sample;
        while (search.reached.spp > 1) {
            const PathTracerSample lower = measure(search.reached.spp / 2);
            if (lower.error > target) {
                search.above = lower;
                break;
            }
            search.reached = lower;
        }
    } else {
        search.above = sample;
        while (search.above.spp * 2 <= max_spp) {
            const PathTracerSample higher = measure(search.above.spp * 2);
            if (higher.error <= target) {
                search.found = true;
                search.reached = higher;
                break;
            }
            search.above = higher;
        }
        if (!search.found) search.reached = search.above;
    }
    search.spp = search.found && search.above.spp > 0 ? interpolated_spp(search.above, search.reached, target)
                                                      : search.reached.spp;
    search.seconds = search.reached.seconds * search.spp / search.reached.spp;
    return search;
}

}  // namespace rad
