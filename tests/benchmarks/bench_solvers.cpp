// Solvers compared: time per step, and steps (and seconds) to reach 1 % and 0.1 % relative error against
// the direct solve, on the Cornell box at 3082 patches (--patch-size 32, reciprocity enforced so that CG
// solves the same system as the others), on the furnace (builtin:cube at 1536 patches, uniform emission,
// ρ = 0.99) and on the same cube lit from the top at ρ = 0.99. Error is measured in power:
// Σ A |B − B_direct| / Σ A |B_direct| over all channels.
//   radiosity_microbench --benchmark_filter=Solver
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <glm/common.hpp>
#include <map>
#include <string>

#include "rad/scene/builtin_scenes.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {
namespace {

struct BenchScene {
    UniformTransport system;
    std::vector<glm::dvec3> reference;  // the direct solve
    double reference_seconds = 0.0;
};

double relative_error(const UniformTransport& system, std::span<const glm::dvec3> b,
                      const std::vector<glm::dvec3>& reference) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
        const glm::dvec3 d = glm::abs(b[i] - reference[i]);
        difference += system.area[i] * (d.x + d.y + d.z);
        total += system.area[i] * (reference[i].x + reference[i].y + reference[i].z);
    }
    return difference / total;
}

BenchScene solved(UniformTransport system) {
    BenchScene scene{std::move(system), {}, 0.0};
    const auto start = std::chrono::steady_clock::now();
    auto direct = make_solver(SolverMethod::direct, scene.system, SolverOptions{});
    direct->step();
    scene.reference_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    scene.reference.assign(direct->solution().begin(), direct->solution().end());
    return scene;
}

const BenchScene& cornell() {
    static const BenchScene scene = [] {
        const Scene cornell_box = make_cornell_box();
        const PatchMesh patches = build_patches(cornell_box, MeshingOptions{.patch_size = 32.0});
        FormFactorOptions form_factors;
        form_factors.enforce_reciprocity = true;
        return solved(
            make_uniform_transport(cornell_box, patches, compute_form_factors(patches, form_factors)));
    }();
    return scene;
}

// builtin:cube at 16 × 16 patches a face, form-factor rows scaled to sum to 1, ρ = 0.99.
UniformTransport high_albedo_cube(bool uniform_emission) {
    static const Scene cube = make_cube();
    static const PatchMesh patches = build_patches(cube, MeshingOptions{.patch_size = 1.0 / 16.0});
    static const FormFactorMatrix f = [] {
        FormFactorOptions form_factors;
        form_factors.normalize_rows = true;
        return compute_form_factors(patches, form_factors);
    }();
    UniformTransport system = make_uniform_transport(cube, patches, f);
    system.reflectance.assign(system.size(), glm::dvec3(0.99));
    if (uniform_emission) system.emission.assign(system.size(), glm::dvec3(1.0));
    return system;
}

const BenchScene& furnace() {
    static const BenchScene scene = solved(high_albedo_cube(true));
    return scene;
}

const BenchScene& top_lit_cube() {
    static const BenchScene scene = solved(high_albedo_cube(false));
    return scene;
}

struct Accuracy {
    double steps_to_1 = NAN, steps_to_01 = NAN;      // NaN: not reached
    double seconds_to_1 = NAN, seconds_to_01 = NAN;  // solver time only, error checks excluded
    double display_steps_to_1 = NAN;                 // southwell's display_solution (with the ambient term)
};

// Runs the method from its first guess until 0.1 % (or it stops), checking the error after every step.
Accuracy accuracy(const BenchScene& scene, SolverMethod method) {
    static std::map<std::pair<const BenchScene*, SolverMethod>, Accuracy> cache;
    if (auto it = cache.find({&scene, method}); it != cache.end()) return it->second;
    SolverOptions options;
    options.tolerance = 0.0;
    options.max_steps = method == SolverMethod::southwell ? 5000 * scene.system.size() : 100'000;
    auto solver = make_solver(method, scene.system, options);
    Accuracy result;
    double seconds = 0.0;
    StepReport report = solver->report();
    for (;;) {
        // A shot is cheap: southwell's error is checked every 64 shots, or the checks would dominate.
        if (method != SolverMethod::southwell || report.step % 64 == 0 || report.finished()) {
            const double error = relative_error(scene.system, solver->solution(), scene.reference);
            const auto step = static_cast<double>(report.step);
            if (std::isnan(result.steps_to_1) && error <= 1e-2) {
                result.steps_to_1 = step;
                result.seconds_to_1 = seconds;
            }
            if (error <= 1e-3) {
                result.steps_to_01 = step;
                result.seconds_to_01 = seconds;
            }
            if (method == SolverMethod::southwell && std::isnan(result.display_steps_to_1) &&
                relative_error(scene.system, solver->display_solution(), scene.reference) <= 1e-2) {
                result.display_steps_to_1 = step;
            }
        }
        if (!std::isnan(result.steps_to_01) || report.finished()) break;
        const auto start = std::chrono::steady_clock::now();
        report = solver->step();
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return cache[{&scene, method}] = result;
}

void BM_SolverStep(benchmark::State& state, const BenchScene& (*scene_of)(), SolverMethod method) {
    const BenchScene& scene = scene_of();
    SolverOptions options;
    options.tolerance = 0.0;
    options.max_steps = 0;
    auto solver = make_solver(method, scene.system, options);
    for (auto _ : state) {
        if (solver->report().finished()) {
            state.PauseTiming();
            solver = make_solver(method, scene.system, options);
            state.ResumeTiming();
        }
        solver->step();
    }
    const Accuracy a = accuracy(scene, method);
    state.counters["patches"] = static_cast<double>(scene.system.size());
    state.counters["nonzeros"] = static_cast<double>(scene.system.form_factors.nonzeros());
    // One sweep touches every nonzero once (jacobi, gauss-seidel, cg): the time per nonzero per step.
    if (method != SolverMethod::southwell && method != SolverMethod::direct) {
        state.counters["s_per_nonzero"] =
            benchmark::Counter(static_cast<double>(scene.system.form_factors.nonzeros()),
                               benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    }
    state.counters["steps_to_1pct"] = a.steps_to_1;
    state.counters["steps_to_0.1pct"] = a.steps_to_01;
    state.counters["s_to_1pct"] = a.seconds_to_1;
    state.counters["s_to_0.1pct"] = a.seconds_to_01;
    if (method == SolverMethod::southwell) state.counters["display_steps_to_1pct"] = a.display_steps_to_1;
    if (method == SolverMethod::direct) state.counters["reference_s"] = scene.reference_seconds;
}

void register_solver_benchmarks() {
    const std::pair<const char*, const BenchScene& (*)()> scenes[] = {
        {"cornell_3082", cornell}, {"furnace_rho_0.99", furnace}, {"top_lit_cube_rho_0.99", top_lit_cube}};
    for (const auto& [scene_name, scene_of] : scenes) {
        for (SolverMethod method : all_solver_methods()) {
            const std::string name =
                "SolverStep/" + std::string(scene_name) + "/" + std::string(solver_method_name(method));
            auto* b = benchmark::RegisterBenchmark(name.c_str(), BM_SolverStep, scene_of, method);
            b->Unit(benchmark::kMillisecond);
            if (method == SolverMethod::direct) b->Iterations(1);
            if (method == SolverMethod::southwell) b->Unit(benchmark::kMicrosecond);
        }
    }
}

const bool registered = (register_solver_benchmarks(), true);

}  // namespace
}  // namespace rad
