#include "bench/bench_report.hpp"

#include <cmath>

#include <cstdio>

#include "bench/error_time_plot.hpp"

namespace rad {

namespace {

std::string format(const char* pattern, double a, double b = 0.0) {
    char text[96];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

std::string percent(double value) {
    if (std::isnan(value)) return "n/a";
    return format("%.2f %%", 100.0 * value);
}

std::string run_table(const BenchResults& results) {
    std::string text =
        "| scene | subdivision | patches | links | form factors | solver | steps | mesh s | form factors s | "
        "solve s | total s | solver error | total error (reference noise) | image error | pixel error |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const BenchRow& r : results.rows) {
        text += "| " + r.scene + " | " + r.subdivision + " | " + std::to_string(r.patches) + " | " +
                std::to_string(r.links) + " | " + r.estimator + " | " + r.solver + " | " +
                std::to_string(r.steps) + (r.converged ? "" : " (not converged)") + " | " +
                format("%.3f | %.3f | ", r.mesh_seconds, r.form_factor_seconds) +
                format("%.3f | %.3f | ", r.solve_seconds, r.seconds()) +
                (std::isnan(r.solver_error) ? std::string("n/a | ")
                                            : format("%.2g %% | ", 100.0 * r.solver_error)) +
                percent(r.total_error) + " (" + percent(r.reference_noise) + ") | " + percent(r.image_error) +
                " | " + percent(r.pixel_error) + " |\n";
    }
    return text;
}

std::string comparison_table(const BenchResults& results) {
    std::string text =
        "| scene | image | radiosity image error | radiosity first image s | "
        "radiosity further view s: viewer frame (render's float frame) | "
        "path tracer measured: spp (image error) | path tracer spp to that error | path tracer s per image | "
        "first: path tracer / radiosity | further: path tracer / radiosity (viewer frame) |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const PathTracerComparison& c : results.comparisons) {
        const PathTracerSearch& p = c.path_tracer;
        std::string measured = std::to_string(p.reached.spp) + " (" + percent(p.reached.error) + ")";
        if (p.above.spp > 0)
            measured = std::to_string(p.above.spp) + " (" + percent(p.above.error) + "), " + measured;
        const std::string spp = p.found ? format("%.0f", p.spp) : "not reached";
        text += "| " + c.scene + " | " + format("%.0f²", c.image_size) + " | " +
                percent(c.radiosity_image_error) + " | " + format("%.3f | ", c.radiosity_first_seconds) +
                format("%.4f (%.4f) | ", c.radiosity_further_seconds, c.radiosity_further_float_seconds) +
                measured + " | " + spp + " | " + format("%.3f | ", p.seconds) +
                format("%.2f | ", p.seconds / c.radiosity_first_seconds) +
                format("%.0f |\n", p.seconds / c.radiosity_further_seconds);
    }
    return text;
}

}  // namespace

std::string bench_table(const BenchResults& results) {
    std::string text = run_table(results);
    if (!results.comparisons.empty()) text += "\n" + comparison_table(results);
    if (!results.notes.empty()) {
        text += "\n";
        for (const std::string& note : results.notes) text += "- " + note + "\n";
    }
    return text;
}

std::string bench_csv(const BenchResults& results) {
    std::string text =
        "scene,subdivision,patches,links,patch_size,form_factors,solver,steps,converged,mesh_s,form_factors_"
        "s,"
        "solve_s,total_s,render_s,solver_error,total_error,reference_noise,image_error,pixel_error\n";
    for (const BenchRow& r : results.rows) {
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s,%s,%zu,%zu,%.9g,%s,%s,%zu,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                      r.scene.c_str(), r.subdivision.c_str(), r.patches, r.links, r.patch_size,
                      r.estimator.c_str(), r.solver.c_str(), r.steps, r.converged ? 1 : 0, r.mesh_seconds,
                      r.form_factor_seconds, r.solve_seconds, r.seconds(), r.render_seconds, r.solver_error,
                      r.total_error, r.reference_noise, r.image_error, r.pixel_error);
        text += line;
    }
    return text;
}

std::string bench_plot_svg(const BenchResults& results) {
    std::vector<PlotPoint> points;
    for (const BenchRow& r : results.rows) {
        if (std::isnan(r.total_error)) continue;
        const std::string scene = r.scene.substr(r.scene.find(':') + 1);
        const std::string series = r.solver == "jacobi" ? r.estimator : r.solver;
        points.push_back({series, scene, r.seconds(), r.total_error});
    }
    return error_time_plot_svg(
        points, {"Total error of patch radiosity against the path tracer",
                 "time from the start: mesh, form factors, solve (s)", "area-weighted relative RMS error"});
}

}  // namespace rad
