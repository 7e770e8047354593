#pragma once

// Runs many paths per item (a point, a patch, a pixel) on all cores: the paths of all items, item by item,
// are cut into fixed tasks; each task traces its paths in batches and sums them per item in path order, and
// the tasks' sums are added in task order, so the result does not depend on the number of threads.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "reference/path_tracer_paths.hpp"

namespace rad::path_tracing {

// Which path: sample `sample` of item `item`. Its random stream is RandomStream(seed, item, sample).
struct PathKey {
    std::uint64_t item = 0;
    std::uint64_t sample = 0;
};

// Fills starts[k] for keys[k], drawing from random[k] (a position on a patch, a camera ray's jitter);
// returns the rays it traced to find them.
using StartFunction =
    std::function<std::uint64_t(std::span<const PathKey> keys, std::span<RandomStream> random,
                                std::span<PathStart> starts, PathScratch& scratch)>;

// Sums of one item's path values, per channel.
struct Accumulator {
    glm::dvec3 sum{0.0};
    glm::dvec3 sum_squares{0.0};
    std::uint64_t count = 0;

    void add(const glm::dvec3& value) {
        sum += value;
        sum_squares += value * value;
        ++count;
    }
    void add(const Accumulator& other) {
        sum += other.sum;
        sum_squares += other.sum_squares;
        count += other.count;
    }
    Estimate estimate() const;
};

// `samples` paths for each of `items` items. Adds the paths and rays to `stats` (its seconds untouched);
// reports paths to `progress` under `stage` and throws Cancelled when it is cancelled.
std::vector<Estimate> run_paths(const PathContext& context, std::size_t items, int samples,
                                const StartFunction& start, PathTracerStats& stats, Progress* progress,
                                const std::string& stage);

}  // namespace rad::path_tracing
