#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "bench/bench_plan.hpp"
#include "bench/path_tracer_search.hpp"
#include "rad/io/image.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// One radiosity run of the sweep, its times and its errors. Errors are relative (0.02 = 2 %); NaN where
// not measured.
struct BenchRow {
    std::string scene;
    std::string subdivision;  // the transport method's name
    std::size_t patches = 0;
    std::size_t links = 0;  // form-factor nonzeros, or hierarchical links
    double patch_size = 0.0;
    std::string estimator;  // "hemisphere 4096"
    std::string solver;
    std::size_t steps = 0;
    bool converged = false;
    double mesh_seconds = 0.0, form_factor_seconds = 0.0, solve_seconds = 0.0, render_seconds = 0.0;
    // Of render_seconds, building the display mesh (the direct light and final gather at its vertices): the
    // first row of a solved mesh pays it, later solvers' rows reuse that display.
    double display_seconds = 0.0;
    double seconds() const { return mesh_seconds + form_factor_seconds + solve_seconds; }
    // Area-weighted relative RMS of patch radiosity against the converged solution of the same form factors.
    double solver_error = 0.0;
    // The same against the path-traced patch reference, and that reference's own noise (its standard
    // errors in the same norm): the error of the reference is at most about this. NaN for hierarchical
    // runs, whose leaves are not the reference's patches (their image error compares them).
    double total_error = 0.0;
    double reference_noise = 0.0;
    // Mean relative error over 8 × 8-pixel blocks of the rendered image against the path-traced one.
    double image_error = 0.0;
    // The same over single pixels, the reference's own pixel noise included (BenchResults::notes give it).
    double pixel_error = 0.0;
};

// The path tracer beside radiosity's first image, at one image size.
struct PathTracerComparison {
    std::string scene;
    int image_size = 0;
    double radiosity_image_error = 0.0;  // of the default run, against the reference at image_size
    // Mesh, form factors, solve, the display mesh (its vertices' direct light and gather) and this render.
    double radiosity_first_seconds = 0.0;
    // One more viewpoint: one frame, as the viewer's window draws it (8-bit sRGB, one sample per pixel), and
    // as `render` draws it (float radiance, 4 samples per pixel).
    double radiosity_further_seconds = 0.0;
    double radiosity_further_float_seconds = 0.0;
    // The path tracer's images at powers of two paths per pixel that bracket radiosity's image error
    // (find_path_tracer_spp), and the paths per pixel and seconds per image interpolated to reach it
    // (first image or further: the path tracer redoes all).
    PathTracerSearch path_tracer;
};

// An image worth keeping for a person to look at: the default run's and the path tracer's, per scene.
struct NamedImage {
    std::string name;  // a file name without folder: "cornell-radiosity.pfm"
    Image image;
};

struct BenchResults {
    std::vector<BenchRow> rows;
    std::vector<NamedImage> images;
    std::vector<PathTracerComparison> comparisons;
    std::vector<std::string> notes;  // the reference work per scene, for the report
};

// Runs the plan on one scene, adding its rows, comparisons and notes. Needs a current OpenGL context.
// `log` receives one line per finished run, for progress.
void run_bench_scene(const std::string& scene, const BenchPlan& plan, BenchResults& results,
                     const std::function<void(const std::string&)>& log);

std::string estimator_label(const EstimatorSetting& setting);

}  // namespace rad
