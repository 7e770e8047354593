#include "reference/path_tracer_runner.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <stdexcept>

namespace rad::path_tracing {

namespace {

// Paths per task: enough to amortize a task, few enough that two cores share small jobs evenly.
constexpr std::size_t kTaskPaths = 4096;
// Paths traced together: the width of the wavefront sent through Embree's stream interface.
constexpr std::size_t kBatchPaths = 1024;

struct Worker {
    PathScratch scratch;
    std::vector<PathKey> keys;
    std::vector<RandomStream> random;
    std::vector<PathStart> starts;
    std::vector<glm::dvec3> values;
};

// The sums of one task: items first_item, first_item + 1, ...
struct TaskSums {
    std::size_t first_item = 0;
    std::vector<Accumulator> items;
    std::uint64_t paths = 0;
};

class Runner {
  public:
    Runner(const PathContext& context, std::size_t items, int samples, const StartFunction& start)
        : context_(context), samples_(static_cast<std::uint64_t>(samples)), start_(start) {
        total_ = items * samples_;
    }

    std::uint64_t total() const { return total_; }
    std::size_t tasks() const { return static_cast<std::size_t>((total_ + kTaskPaths - 1) / kTaskPaths); }

    // Traces the paths of task t; returns their sums and adds the rays traced to `rays`.
    TaskSums run_task(std::size_t t, Worker& w, std::uint64_t& rays) const {
        const std::uint64_t begin = static_cast<std::uint64_t>(t) * kTaskPaths;
        const std::uint64_t end = std::min<std::uint64_t>(total_, begin + kTaskPaths);
        TaskSums sums;
        sums.paths = end - begin;
        sums.first_item = static_cast<std::size_t>(begin / samples_);
        sums.items.resize(static_cast<std::size_t>((end - 1) / samples_) - sums.first_item + 1);
        for (std::uint64_t first = begin; first < end; first += kBatchPaths) {
            const auto count = static_cast<std::size_t>(std::min<std::uint64_t>(kBatchPaths, end - first));
            prepare_batch(first, count, w);
            rays += start_(w.keys, w.random, w.starts, w.scratch);
            rays += context_.trace(w.starts, w.random, w.values, w.scratch);
            for (std::size_t k = 0; k < count; ++k) {
                sums.items[static_cast<std::size_t>(w.keys[k].item) - sums.first_item].add(w.values[k]);
            }
        }
        return sums;
    }

  private:
    void prepare_batch(std::uint64_t first, std::size_t count, Worker& w) const {
        w.keys.resize(count);
        w.random.clear();
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint64_t path = first + k;
            w.keys[k] = {path / samples_, path % samples_};
            w.random.emplace_back(context_.options().seed, w.keys[k].item, w.keys[k].sample);
        }
        w.starts.assign(count, PathStart{});
        w.values.resize(count);
    }

    const PathContext& context_;
    std::uint64_t samples_;
    std::uint64_t total_ = 0;
    const StartFunction& start_;
};

}  // namespace

Estimate Accumulator::estimate() const {
    Estimate e;
    if (count == 0) return e;
    const auto n = static_cast<double>(count);
    e.mean = sum / n;
    if (count > 1) {
        const glm::dvec3 variance = glm::max(sum_squares - n * e.mean * e.mean, glm::dvec3(0.0)) / (n - 1.0);
        e.standard_error = glm::sqrt(variance / n);
    }
    return e;
}

std::vector<Estimate> run_paths(const PathContext& context, std::size_t items, int samples,
                                const StartFunction& start, PathTracerStats& stats, Progress* progress,
                                const std::string& stage) {
    if (samples <= 0)
        throw std::invalid_argument("path tracer: the number of paths per item must be positive");
    const Runner runner(context, items, samples, start);
    if (progress) progress->begin(stage, runner.total());
    std::vector<TaskSums> sums(runner.tasks());
    tbb::enumerable_thread_specific<Worker> workers;
    std::atomic<std::uint64_t> rays{0};
    std::atomic<bool> cancelled{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sums.size(), 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          Worker& worker = workers.local();
                          for (std::size_t t = range.begin(); t != range.end(); ++t) {
                              if (cancelled || (progress && progress->cancelled())) {
                                  cancelled = true;
                                  return;
                              }
                              std::uint64_t task_rays = 0;
                              sums[t] = runner.run_task(t, worker, task_rays);
                              rays += task_rays;
                              if (progress) progress->advance(sums[t].paths);
                          }
                      });
    if (cancelled) throw Cancelled{};

    std::vector<Accumulator> totals(items);
    for (const TaskSums& task : sums) {
        for (std::size_t i = 0; i < task.items.size(); ++i) totals[task.first_item + i].add(task.items[i]);
    }
    std::vector<Estimate> estimates(items);
    for (std::size_t i = 0; i < items; ++i) estimates[i] = totals[i].estimate();
    stats.paths += runner.total();
    stats.rays += rays;
    return estimates;
}

}  // namespace rad::path_tracing
