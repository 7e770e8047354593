// A display built from a solution (the mesh, the emitters' light traced at its vertices and the gathers)
// against the same display relit by another solution of the same elements (relight_display: no ray), on the
// built-in scenes solved as `solve` solves them by default.
//   radiosity_microbench --benchmark_filter=Display
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "pipeline/radiosity_pipeline.hpp"
#include "rad/display/solution_display.hpp"

namespace rad {
namespace {

const char* const kScenes[] = {"builtin:cornell", "builtin:white-room"};

const RadiosityPipeline& solved(const std::string& scene) {
    static std::map<std::string, std::unique_ptr<RadiosityPipeline>> pipelines;
    std::unique_ptr<RadiosityPipeline>& pipeline = pipelines[scene];
    if (!pipeline) {
        PipelineOptions options;
        options.scene.scene = scene;
        pipeline = std::make_unique<RadiosityPipeline>(options);
        pipeline->solve();
    }
    return *pipeline;
}

void BM_DisplayBuild(benchmark::State& state) {
    const RadiosityPipeline& pipeline = solved(kScenes[state.range(0)]);
    for (auto _ : state) benchmark::DoNotOptimize(pipeline.build_display({}).vertex_count());
    state.SetLabel(kScenes[state.range(0)]);
}
BENCHMARK(BM_DisplayBuild)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DisplayRelight(benchmark::State& state) {
    const RadiosityPipeline& pipeline = solved(kScenes[state.range(0)]);
    DisplayMesh display = pipeline.build_display({});
    for (auto _ : state) {
        relight_display(display, pipeline.loaded().scene, pipeline.solution());
        benchmark::DoNotOptimize(display.light.direct.vertex.data());
    }
    state.SetLabel(kScenes[state.range(0)]);
}
BENCHMARK(BM_DisplayRelight)->DenseRange(0, 1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace rad
