// The Monte Carlo reference's speed on the Cornell box at the default patch size (2516 patches): patch
// radiosities (paths from random points on every patch) and a reference image from the scene's camera, with
// paths and rays per second as counters. All cores unless --benchmark_filter picks the /threads:1 cases.
//   radiosity_microbench --benchmark_filter=PathTracer
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <optional>

#include "rad/reference/path_tracer.hpp"
#include "rad/scene/builtin_scenes.hpp"

namespace rad {
namespace {

struct CornellBox {
    Scene scene = make_cornell_box();
    PatchMesh patches = build_patches(scene, MeshingOptions{});
};

const CornellBox& cornell() {
    static const CornellBox box;
    return box;
}

void report(benchmark::State& state, const PathTracerStats& total) {
    state.counters["paths/s"] =
        benchmark::Counter(static_cast<double>(total.paths), benchmark::Counter::kIsRate);
    state.counters["rays/s"] =
        benchmark::Counter(static_cast<double>(total.rays), benchmark::Counter::kIsRate);
    state.counters["rays/path"] = static_cast<double>(total.rays) / static_cast<double>(total.paths);
}

void BM_PathTracerPatchRadiosity(benchmark::State& state) {
    std::optional<tbb::global_control> threads;  // range(0) threads, or all of them for 0
    if (state.range(0) > 0) {
        threads.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<std::size_t>(state.range(0)));
    }
    const PathTracer tracer(cornell().scene, cornell().patches);
    PathTracerStats total;
    for (auto _ : state) {
        PathTracerStats stats;
        benchmark::DoNotOptimize(tracer.patch_radiosity(64, &stats));
        total.paths += stats.paths;
        total.rays += stats.rays;
    }
    report(state, total);
}
BENCHMARK(BM_PathTracerPatchRadiosity)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_PathTracerImage(benchmark::State& state) {
    const PathTracer tracer(cornell().scene, cornell().patches);
    PathTracerStats total;
    for (auto _ : state) {
        const ReferenceImage image = tracer.render(*cornell().scene.camera, 128, 128, 16);
        total.paths += image.stats.paths;
        total.rays += image.stats.rays;
    }
    report(state, total);
}
BENCHMARK(BM_PathTracerImage)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace rad
