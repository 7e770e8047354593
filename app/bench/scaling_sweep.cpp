#include "bench/scaling_sweep.hpp"

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "bench/peak_memory.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/scene/builtin_scenes.hpp"

namespace rad {

namespace {

double detail(const TransportReport& report, const std::string& name) {
    for (const TransportDetail& d : report.details)
        if (d.name == name) return d.value;
    return 0.0;
}

double furnace_error(std::span<const glm::dvec3> radiosity) {
    const double expected = kFurnaceEmission / (1.0 - kFurnaceReflectance);
    double worst = 0.0;
    for (const glm::dvec3& b : radiosity)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(b[c] - expected) / expected);
    return worst;
}

ScalingRow run_furnace(const std::string& spelled, Subdivision method, bool& peak_per_run) {
    ScalingRow row;
    row.scene = "builtin:furnace-" + spelled;
    row.subdivision = std::string(subdivision_name(method));
    // What the last run freed goes back to the system first, so this run's peak is its own.
    malloc_trim(0);
    peak_per_run = reset_peak_resident() && peak_per_run;
    PipelineOptions options;
    options.scene.scene = row.scene;
    options.subdivision.method = row.subdivision;
    try {
        RadiosityPipeline pipeline(options);
        for (const Surface& s : pipeline.loaded().scene.surfaces) row.faces += s.mesh.n_faces();
        row.patches = pipeline.loaded().patches->size();
        const StepReport& report = pipeline.solve();
        const TransportReport transport = pipeline.transport().report();
        row.elements = transport.elements;
        row.links = transport.interactions;
        row.clusters = static_cast<std::size_t>(detail(transport, "clusters"));
        row.steps = report.step;
        row.solver = std::string(solver_method_name(pipeline.method()));
        row.converged = report.status == SolverStatus::converged;
        row.mesh_seconds = pipeline.seconds().mesh;
        row.build_seconds = pipeline.seconds().form_factors;
        row.solve_seconds = pipeline.seconds().solve;
        row.furnace_error = furnace_error(pipeline.solver().solution());
    } catch (const std::exception& e) {
        row.failure = e.what();
    }
    row.peak_bytes = peak_resident_bytes();
    return row;
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace

ScalingPlan default_scaling_plan(bool quick) {
    ScalingPlan plan;
    plan.faces = quick ? std::vector<std::string>{"1k", "2k"}
                       : std::vector<std::string>{"1k", "3k", "10k", "30k", "100k", "300k", "1m"};
    // The methods `auto` chooses between: the one it takes at any size first, then those it takes up to a
    // size, which run on the furnaces up to 100k faces (above, form factors take minutes and gigabytes).
    const std::size_t limited_max_faces = quick ? 2'000 : 100'000;
    const auto methods = transport_methods();
    for (auto m = methods.rbegin(); m != methods.rend(); ++m) {
        if (m->automatic_up_to == kAnySize)
            plan.methods.insert(plan.methods.begin(), {m->id});
        else if (m->automatic_up_to > 0)
            plan.methods.push_back({m->id, limited_max_faces});
    }
    return plan;
}

Crossover scaling_crossover(const std::vector<ScalingRow>& rows, const std::string& faster,
                            const std::string& other) {
    // Per size, the two methods' times, in the plan's order (ascending sizes); the patches are the other's
    // (the uniform mesh's, in the plan).
    struct Pair {
        std::size_t faces = 0, other_patches = 0;
        double other = 0.0, faster = 0.0;
    };
    std::vector<Pair> pairs;
    for (const ScalingRow& o : rows) {
        if (o.subdivision != other || !o.failure.empty()) continue;
        for (const ScalingRow& f : rows) {
            if (f.subdivision == faster && f.scene == o.scene && f.failure.empty())
                pairs.push_back({o.faces, o.patches, o.seconds(), f.seconds()});
        }
    }
    Crossover out;
    if (pairs.empty()) {
        out.text = "no size ran both ways";
        return out;
    }
    const std::string patches = " " + other + " patches)";
    const auto is_faster = [](const Pair& p) { return p.faster < p.other; };
    const auto first = std::find_if(pairs.begin(), pairs.end(), is_faster);
    if (first == pairs.end()) {
        out.text = other + " was faster at every size both ran, up to " + std::to_string(pairs.back().faces) +
                   " faces (" + std::to_string(pairs.back().other_patches) + patches;
        return out;
    }
    if (first == pairs.begin()) {
        out.found = true;
        out.text = faster + " was faster at every size both ran, from " + std::to_string(first->faces) +
                   " faces (" + std::to_string(first->other_patches) + patches;
        return out;
    }
    // The ratio of times crosses 1 between the two sizes: interpolated in log(ratio) against log(faces).
    const Pair& a = *(first - 1);
    const Pair& b = *first;
    const double ra = std::log(a.faster / a.other), rb = std::log(b.faster / b.other);
    const double t = ra / (ra - rb);
    const auto at = [t](double x, double y) {
        return std::exp(std::log(x) + t * (std::log(y) - std::log(x)));
    };
    out.found = true;
    out.text = faster + " gets faster than " + other +
               format(" at about %.0f faces", at(double(a.faces), double(b.faces))) +
               format(" (%.0f", at(double(a.other_patches), double(b.other_patches))) + patches + ": " +
               other + " was faster at " + std::to_string(a.faces) + " faces (" +
               format("%.2f s against ", a.other) + format("%.2f s), ", a.faster) + faster + " at " +
               std::to_string(b.faces) + " (" + format("%.2f s against ", b.faster) +
               format("%.2f s)", b.other);
    return out;
}

void check_scaling_plan(const ScalingPlan& plan) {
    for (const std::string& spelled : plan.faces) furnace_faces("furnace-" + spelled);
}

void run_scaling(const ScalingPlan& plan, ScalingResults& results,
                 const std::function<void(const ScalingResults&)>& row_done,
                 const std::function<void(const std::string&)>& log) {
    bool peak_per_run = true;
    if (plan.methods.size() >= 2) {
        results.faster = subdivision_name(plan.methods[0].method);
        results.other = subdivision_name(plan.methods[1].method);
    }
    for (const std::string& spelled : plan.faces) {
        for (const ScalingMethod& method : plan.methods) {
            if (furnace_faces("furnace-" + spelled) > method.max_faces) continue;
            const ScalingRow row = run_furnace(spelled, method.method, peak_per_run);
            if (row.failure.empty()) {
                log(format("%8.2f s  ", row.seconds()) + row.scene + "  " + row.subdivision + "  " +
                    std::to_string(row.elements) + " elements  " + std::to_string(row.links) + " links" +
                    format("  build %.2f s", row.build_seconds) +
                    format("  solve %.2f s", row.solve_seconds) +
                    format("  peak %.0f MB", double(row.peak_bytes) / 1e6) +
                    format("  furnace error %.2g", row.furnace_error));
            } else {
                log(row.scene + "  " + row.subdivision + "  failed: " + row.failure);
            }
            results.rows.push_back(row);
            row_done(results);
        }
    }
    if (!peak_per_run) {
        results.notes.push_back(
            "peak memory is the process's since it started (this system cannot reset it between runs)");
    }
}

}  // namespace rad
