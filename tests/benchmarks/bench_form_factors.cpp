// Form factors on the Cornell box: the hemisphere pass's rays per second against Embree's own throughput on
// the same rays, and the time, memory and accuracy of the whole pass at several patch counts.
//
//   radiosity_microbench --benchmark_filter='BM_Rays'     rays per second (a few seconds)
//   radiosity_microbench --benchmark_filter='BM_Pass'     the passes at 1k .. 80k patches (minutes)
//
// Accuracy: surface-to-surface factors F_ST = Σ_{i in S} A_i Σ_{j in T} F_ij / A_S do not depend on the
// mesh, so each pass is compared with the other estimator's finest pass (analytic at 5k patches for the
// hemisphere passes, hemisphere at 80k for the analytic ones) over the pairs of surfaces with F_ST > 0.01.
#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <map>
#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "transport/uniform/form_factors_hemisphere.hpp"

namespace rad {
namespace {

// The patch size that cuts the Cornell box into about `target` patches (counts fall as size grows).
double patch_size_for(const Scene& scene, std::size_t target) {
    double lo = 1.0, hi = 1000.0;
    for (int step = 0; step < 60; ++step) {
        const double mid = std::sqrt(lo * hi);
        (count_patches(scene, mid) > target ? lo : hi) = mid;
    }
    return hi;
}

PatchMesh cornell_patches(std::size_t target) {
    static const Scene cornell = make_cornell_box();
    MeshingOptions meshing;
    meshing.patch_size = patch_size_for(cornell, target);
    return build_patches(cornell, meshing);
}

// ---- Rays per second ---------------------------------------------------------------------------------

constexpr std::size_t kRayPatches = 5000;
constexpr int kRaysPerPatch = 1024;
constexpr std::uint64_t kSeed = 1;
constexpr std::size_t kChunk = 256;  // rays per query, as the pass traces them

struct RayFixture {
    PatchMesh patches = cornell_patches(kRayPatches);
    RayScene scene{patches};
    std::vector<Ray> rays;  // exactly the pass's rays, patch by patch

    RayFixture() {
        rays.resize(patches.size() * kRaysPerPatch);
        std::vector<double> weights(kRaysPerPatch);
        const double offset = ray_offset(patches);
        for (std::uint32_t i = 0; i < patches.size(); ++i) {
            hemisphere_rays(patches, i, kSeed, offset,
                            std::span(rays).subspan(i * kRaysPerPatch, kRaysPerPatch), weights);
        }
    }
};

RayFixture& ray_fixture() {
    static RayFixture fixture;
    return fixture;
}

template <class Query>
void trace_all(const std::vector<Ray>& rays, Query&& query) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size() / kChunk), [&](const auto& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) query(std::span(rays).subspan(c * kChunk, kChunk));
    });
}

void set_rays_per_second(benchmark::State& state, std::size_t rays_per_iteration) {
    state.counters["rays_per_second"] = benchmark::Counter(static_cast<double>(rays_per_iteration),
                                                           benchmark::Counter::kIsIterationInvariantRate);
    state.counters["patches"] = static_cast<double>(ray_fixture().patches.size());
}

// Embree's occlusion queries on the pass's rays: the throughput the issue compares with.
void BM_RaysEmbreeOccluded(benchmark::State& state) {
    RayFixture& f = ray_fixture();
    for (auto _ : state) {
        trace_all(f.rays, [&](std::span<const Ray> rays) {
            std::array<std::uint8_t, kChunk> blocked;
            f.scene.occluded(rays, blocked);
            benchmark::DoNotOptimize(blocked);
        });
    }
    set_rays_per_second(state, f.rays.size());
}
BENCHMARK(BM_RaysEmbreeOccluded)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// Embree's closest-hit queries on the same rays: the pass needs the hit patch, so this bounds it.
void BM_RaysEmbreeIntersect(benchmark::State& state) {
    RayFixture& f = ray_fixture();
    for (auto _ : state) {
        trace_all(f.rays, [&](std::span<const Ray> rays) {
            std::array<RayHit, kChunk> hits;
            f.scene.intersect(rays, hits);
            benchmark::DoNotOptimize(hits);
        });
    }
    set_rays_per_second(state, f.rays.size());
}
BENCHMARK(BM_RaysEmbreeIntersect)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// The whole hemisphere pass on the same patches, seed and rays: generation, tracing, accumulation,
// assembly and diagnostics.
void BM_RaysHemispherePass(benchmark::State& state) {
    RayFixture& f = ray_fixture();
    FormFactorOptions options;
    options.rays = kRaysPerPatch;
    options.seed = kSeed;
    for (auto _ : state) benchmark::DoNotOptimize(compute_form_factors(f.patches, options));
    set_rays_per_second(state, f.patches.size() * kRaysPerPatch);
}
BENCHMARK(BM_RaysHemispherePass)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// ---- The pass at several patch counts ------------------------------------------------------------------

using SurfaceFactors = std::vector<std::vector<double>>;

SurfaceFactors surface_factors(const FormFactorMatrix& f, const PatchMesh& mesh) {
    const std::size_t surfaces = mesh.surface_begin.size() - 1;
    SurfaceFactors out(surfaces, std::vector<double>(surfaces, 0.0));
    std::vector<double> area(surfaces, 0.0);
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
        const std::uint32_t s = mesh.patches[i].surface;
        area[s] += mesh.patches[i].area;
        const FormFactorRow row = f.row(i);
        for (std::size_t k = 0; k < row.size(); ++k)
            out[s][mesh.patches[row.columns[k]].surface] += mesh.patches[i].area * row.values[k];
    }
    for (std::size_t s = 0; s < surfaces; ++s)
        for (double& v : out[s]) v /= area[s];
    return out;
}

// The largest relative difference over the pairs of surfaces that exchange more than 1 %.
double largest_difference(const SurfaceFactors& a, const SurfaceFactors& reference) {
    double worst = 0.0;
    for (std::size_t s = 0; s < a.size(); ++s) {
        for (std::size_t t = 0; t < a.size(); ++t) {
            if (reference[s][t] > 0.01) worst = std::max(worst, std::abs(a[s][t] / reference[s][t] - 1.0));
        }
    }
    return worst;
}

double resident_megabytes() {
    std::ifstream statm("/proc/self/statm");
    double size = 0.0, resident = 0.0;
    statm >> size >> resident;
    return resident * static_cast<double>(::sysconf(_SC_PAGESIZE)) / 1e6;
}

struct PassResult {
    SurfaceFactors factors;
    FormFactorReport report;
};

// Each pass's surface factors, kept for the comparisons of later passes.
std::map<std::pair<FormFactorMethod, std::size_t>, SurfaceFactors>& finished_passes() {
    static std::map<std::pair<FormFactorMethod, std::size_t>, SurfaceFactors> passes;
    return passes;
}

PassResult run_pass(FormFactorMethod method, std::size_t target, benchmark::State& state) {
    const PatchMesh mesh = cornell_patches(target);
    FormFactorOptions options;
    options.method = method;
    PassResult result;
    const double resident_before = resident_megabytes();
    double resident_with_matrix = 0.0;
    for (auto _ : state) {
        const FormFactorMatrix f = compute_form_factors(mesh, options, &result.report);
        resident_with_matrix = resident_megabytes();
        result.factors = surface_factors(f, mesh);
    }
    state.counters["patches"] = static_cast<double>(mesh.size());
    state.counters["nonzeros"] = static_cast<double>(result.report.nonzeros);
    state.counters["matrix_MB"] = static_cast<double>(result.report.memory_bytes) / 1e6;
    state.counters["rss_growth_MB"] = resident_with_matrix - resident_before;
    state.counters["rays_per_second"] = static_cast<double>(result.report.rays) / result.report.seconds;
    state.counters["max_reciprocity_error"] = result.report.max_reciprocity_error;
    state.counters["mean_reciprocity_error"] = result.report.mean_reciprocity_error;
    finished_passes()[{method, target}] = result.factors;
    return result;
}

// Compares with the other estimator's finest pass that has run so far (the filter decides which ran).
void set_cross_error(benchmark::State& state, const PassResult& result, FormFactorMethod other) {
    const SurfaceFactors* reference = nullptr;
    std::size_t finest = 0;
    for (const auto& [key, factors] : finished_passes()) {
        if (key.first == other && key.second > finest) {
            finest = key.second;
            reference = &factors;
        }
    }
    if (!reference) return;
    state.counters["cross_error"] = largest_difference(result.factors, *reference);
    state.counters["cross_reference_patches"] = static_cast<double>(finest);
}

void BM_PassAnalytic(benchmark::State& state) {
    const PassResult r =
        run_pass(FormFactorMethod::analytic, static_cast<std::size_t>(state.range(0)), state);
    set_cross_error(state, r, FormFactorMethod::hemisphere);
}

void BM_PassHemisphere(benchmark::State& state) {
    const PassResult r =
        run_pass(FormFactorMethod::hemisphere, static_cast<std::size_t>(state.range(0)), state);
    set_cross_error(state, r, FormFactorMethod::analytic);
}

// Analytic first, so the hemisphere passes compare with analytic at 5k; the analytic passes compare with the
// hemisphere passes when run again after them (BM_PassAnalyticAgain).
BENCHMARK(BM_PassAnalytic)->Arg(1000)->Arg(5000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_PassHemisphere)
    ->Arg(5000)
    ->Arg(20000)
    ->Arg(80000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// The analytic passes' error against the finest hemisphere pass, which only exists once it has run.
void BM_PassAnalyticAgainstHemisphere(benchmark::State& state) {
    const auto target = static_cast<std::size_t>(state.range(0));
    const auto found = finished_passes().find({FormFactorMethod::analytic, target});
    for (auto _ : state) benchmark::DoNotOptimize(found);
    if (found == finished_passes().end()) return;
    PassResult r;
    r.factors = found->second;
    set_cross_error(state, r, FormFactorMethod::hemisphere);
}
BENCHMARK(BM_PassAnalyticAgainstHemisphere)
    ->Arg(1000)
    ->Arg(5000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rad
