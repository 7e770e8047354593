#include "bench/bench_sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>

#include "gl/scene_image_renderer.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/camera/camera_view.hpp"
#include "rad/reference/image_error.hpp"
#include "rad/reference/path_tracer.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// The method whose meshes the sweep compares: the one `auto` takes for a small scene (a form-factor matrix,
// which every solver can run on).
const TransportMethod& mesh_method() {
    return automatic_transport_method(0);
}

PipelineOptions pipeline_options(const std::string& scene, double patch_size, const EstimatorSetting& setting,
                                 const BenchPlan& plan) {
    PipelineOptions options;
    options.scene.scene = scene;
    options.scene.patch_size = patch_size;
    // The meshes of the sweep are those of the method `auto` takes for small scenes; run_subdivided sets its
    // own.
    options.subdivision.method = std::string(mesh_method().name);
    options.form_factors.method = setting.method;
    options.form_factors.rays = setting.rays;
    options.solver.tolerance = plan.tolerance;
    return options;
}

std::vector<glm::dvec3> solved_radiosity(SolverMethod method, const Transport& transport,
                                         const SolverOptions& options) {
    const std::unique_ptr<Solver> solver = make_solver(method, transport, options);
    run_to_end(*solver);
    return {solver->solution().begin(), solver->solution().end()};
}

// The exact solution of these form factors: a direct solve where it is affordable, else Gauss-Seidel to a
// residual of 1e-12 (the same system, so the same answer to rounding). Not CG, which solves the
// reciprocity-symmetrized system and so answers slightly differently for estimated form factors.
std::vector<glm::dvec3> converged_solution(const Transport& transport, std::size_t patches,
                                           const BenchPlan& plan) {
    SolverOptions options;
    options.tolerance = 1e-12;
    options.max_steps = 1'000'000;
    const bool direct = patches <= plan.direct_max_patches;
    return solved_radiosity(direct ? SolverMethod::direct : SolverMethod::gauss_seidel, transport, options);
}

// Patch radiosity of the path tracer on this mesh, and its noise in the norm of relative_rms_difference.
struct PatchReference {
    std::vector<glm::dvec3> radiosity;
    double noise = 0.0;
    double seconds = 0.0;
    int paths_per_patch = 0;
};

PatchReference patch_reference(const LoadedScene& loaded, const BenchPlan& plan) {
    PatchReference reference;
    const std::size_t n = loaded.patches->size();
    reference.paths_per_patch = static_cast<int>(
        std::max<std::size_t>(plan.min_paths_per_patch, plan.reference_paths / std::max<std::size_t>(n, 1)));
    const PathTracer tracer(loaded.scene, *loaded.patches);
    PathTracerStats stats;
    const std::vector<Estimate> estimates = tracer.patch_radiosity(reference.paths_per_patch, &stats);
    std::vector<glm::dvec3> errors;
    for (const Estimate& e : estimates) {
        reference.radiosity.push_back(e.mean);
        errors.push_back(e.mean + e.standard_error);
    }
    reference.noise = relative_rms_difference(*loaded.patches, errors, reference.radiosity);
    reference.seconds = stats.seconds;
    return reference;
}

class SceneSweep {
  public:
    SceneSweep(const std::string& scene, const BenchPlan& plan, BenchResults& results,
               const std::function<void(const std::string&)>& log)
        : scene_(scene), plan_(plan), results_(results), log_(log) {}

    void run() {
        SceneOptions options;
        options.scene = scene_;
        const LoadedScene base = load_and_mesh(options);
        default_size_ = base.patch_size;
        camera_ = scene_camera(base.scene);
        reference_image_ =
            render_reference(base, plan_.image_size, plan_.reference_spp, plan_.reference_spp * 7919);
        const double noise = block_relative_noise(reference_image_.image, reference_image_.standard_error);
        const double pixel_noise = block_relative_noise(
            reference_image_.image, reference_image_.standard_error, ImageErrorOptions{.block_size = 1});
        results_.notes.push_back(scene_ + ": reference image " + std::to_string(plan_.image_size) + "² at " +
                                 std::to_string(plan_.reference_spp) + " paths per pixel, " +
                                 format("%.1f s", reference_image_.stats.seconds) +
                                 format(", noise %.2f %% in the image error's measure", 100 * noise) +
                                 format(" and %.2f %% in the pixel error's", 100 * pixel_noise) +
                                 " (an exact image's errors would be about these; the true error is about "
                                 "sqrt(error^2 - noise^2))");
        // Radiosity is set beside the path tracer at the default mesh, or the one nearest it.
        const auto nearest_default = std::min_element(
            plan_.size_factors.begin(), plan_.size_factors.end(),
            [](double a, double b) { return std::abs(std::log(a)) < std::abs(std::log(b)); });
        for (double factor : plan_.size_factors)
            run_level(factor * default_size_, factor == *nearest_default);
        for (const RefinedRuns& runs : plan_.refined)
            for (double tolerance : runs.tolerances) run_subdivided(transport_method(runs.method), tolerance);
    }

  private:
    ReferenceImage render_reference(const LoadedScene& loaded, int size, int spp, std::uint64_t seed) const {
        PathTracerOptions options;
        options.seed = seed;
        return PathTracer(loaded.scene, *loaded.patches, options).render(camera_, size, size, spp);
    }

    void run_level(double patch_size, bool is_default_size) {
        std::optional<PatchReference> reference;
        for (std::size_t e = 0; e < plan_.estimators.size(); ++e) {
            const EstimatorSetting& setting = plan_.estimators[e];
            RadiosityPipeline pipeline(pipeline_options(scene_, patch_size, setting, plan_));
            const std::size_t n = pipeline.loaded().patches->size();
            if (setting.method == FormFactorMethod::analytic && n > plan_.analytic_max_patches) continue;
            if (!reference) {
                reference = patch_reference(pipeline.loaded(), plan_);
                results_.notes.push_back(
                    scene_ + format(": patch reference at patch size %.4g, ", patch_size) +
                    std::to_string(n) + " patches × " + std::to_string(reference->paths_per_patch) +
                    format(" paths, %.1f s", reference->seconds) +
                    format(", noise %.2f %%", 100.0 * reference->noise));
            }
            pipeline.prepare();
            const std::vector<glm::dvec3> converged = converged_solution(pipeline.transport(), n, plan_);
            const bool all_solvers = e == 0;
            for (std::size_t s = 0; s < (all_solvers ? plan_.solvers.size() : 1); ++s) {
                const SolverMethod method = plan_.solvers[s];
                if (method == SolverMethod::direct && n > plan_.direct_max_patches) continue;
                BenchRow row = run_solver(pipeline, method, setting, *reference, converged);
                row.patch_size = patch_size;
                log_(format("%8.3f s  ", row.seconds()) + row.scene + "  " + std::to_string(row.patches) +
                     " patches  " + row.estimator + "  " + row.solver +
                     format("  total error %.2f %%", 100 * row.total_error) +
                     format("  image error %.2f %%", 100 * row.image_error));
                results_.rows.push_back(row);
                if (is_default_size && e == 0 && s == 0) keep_images();
                if (is_default_size && e == 0 && s == 0 && scene_ == plan_.scenes.front()) {
                    compare_with_path_tracer(pipeline, row);
                }
            }
        }
    }

    // Adaptive, hierarchical or clustered subdivision with default first or base patches: times, form factors
    // or links, and the image error (the leaves are not the patch reference's patches).
    void run_subdivided(const TransportMethod& transport, double tolerance) {
        const std::string method(transport.name);
        PipelineOptions options = pipeline_options(scene_, 0.0, {FormFactorMethod::hemisphere, 0}, plan_);
        options.subdivision.method = method;
        options.subdivision.tolerance = tolerance;
        RadiosityPipeline pipeline(options);
        // A method whose first pass links every pair of base patches is skipped past its practical size (a
        // furnished room's 30,000 base patches took hierarchical radiosity over 15 minutes).
        if (pipeline.loaded().patches->size() > transport.practical_base_patches) {
            results_.notes.push_back(scene_ + ": " + method + " not run, " +
                                     std::to_string(pipeline.loaded().patches->size()) +
                                     " base patches (its first links are every pair of them)");
            return;
        }
        const auto start = std::chrono::steady_clock::now();
        const StepReport& report = pipeline.solve();
        BenchRow row;
        row.solve_seconds = seconds_since(start) - pipeline.seconds().form_factors;
        row.scene = scene_;
        row.subdivision = method;
        row.patches = pipeline.patches().size();
        row.links = pipeline.transport().report().interactions;
        row.patch_size = pipeline.loaded().patch_size;
        row.estimator =
            (transport.has_matrix ? "hemisphere " + std::to_string(kDefaultHemisphereRays) : "links") +
            format(" tol %.3g", tolerance);
        row.solver = std::string(solver_method_name(pipeline.method()));
        row.steps = report.step;
        row.converged = report.status == SolverStatus::converged;
        row.mesh_seconds = pipeline.seconds().mesh;
        row.form_factor_seconds = pipeline.seconds().form_factors;
        row.solver_error = row.total_error = row.reference_noise = std::numeric_limits<double>::quiet_NaN();
        const Image image =
            SceneImageRenderer(pipeline, false).render(camera_, plan_.image_size, plan_.image_size);
        row.image_error = block_relative_error(image, reference_image_.image);
        row.pixel_error = pixel_relative_error(image, reference_image_.image);
        log_(format("%8.3f s  ", row.seconds()) + row.scene + "  " + method + "  " +
             std::to_string(row.patches) + " leaves  " + std::to_string(row.links) + " links" +
             format("  image error %.2f %%", 100 * row.image_error));
        results_.rows.push_back(row);
    }

    BenchRow run_solver(RadiosityPipeline& pipeline, SolverMethod method, const EstimatorSetting& setting,
                        const PatchReference& reference, const std::vector<glm::dvec3>& converged) {
        SolverCommandOptions command;
        command.method = std::string(solver_method_name(method));
        command.tolerance = plan_.tolerance;
        const std::size_t n = pipeline.loaded().patches->size();
        const auto start = std::chrono::steady_clock::now();
        pipeline.restart_solver(method, solver_options(command, n));
        const StepReport& report = pipeline.solve();
        BenchRow row;
        row.solve_seconds = seconds_since(start);
        row.scene = scene_;
        row.subdivision = std::string(subdivision_name(pipeline.subdivision()));
        row.patches = n;
        row.links = pipeline.transport().report().interactions;
        row.estimator = estimator_label(setting);
        row.solver = command.method;
        row.steps = report.step;
        row.converged = report.status == SolverStatus::converged;
        row.mesh_seconds = pipeline.seconds().mesh;
        row.form_factor_seconds = pipeline.seconds().form_factors;
        const std::span<const glm::dvec3> solution = pipeline.solver().solution();
        row.solver_error = relative_rms_difference(*pipeline.loaded().patches, solution, converged);
        // The path tracer averages over whole patches, covered parts included.
        const std::vector<glm::dvec3> whole =
            whole_patch_radiosity(pipeline.transport(), *pipeline.loaded().patches, solution);
        row.total_error = relative_rms_difference(*pipeline.loaded().patches, whole, reference.radiosity);
        row.reference_noise = reference.noise;
        const auto render_start = std::chrono::steady_clock::now();
        pipeline.display();
        row.display_seconds = seconds_since(render_start);
        const Image image =
            SceneImageRenderer(pipeline, false).render(camera_, plan_.image_size, plan_.image_size);
        row.render_seconds = seconds_since(render_start);
        row.image_error = block_relative_error(image, reference_image_.image);
        row.pixel_error = pixel_relative_error(image, reference_image_.image);
        last_image_ = image;
        return row;
    }

    // The default run's image and the path tracer's, for a person to compare.
    void keep_images() {
        // builtin:NAME gives NAME; a file its name without folder or extension.
        const std::string name = scene_.starts_with("builtin:")
                                     ? scene_.substr(scene_.find(':') + 1)
                                     : std::filesystem::path(scene_).stem().string();
        results_.images.push_back({name + "-radiosity.pfm", last_image_});
        results_.images.push_back({name + "-path-traced.pfm", reference_image_.image});
    }

    // The path tracer's error at `spp` paths per pixel: against the reference at the reference's size,
    // else against a second image of other seeds (both unbiased, so their block differences are noise, and
    // one image's error is the difference over √2).
    double path_tracer_error(const ReferenceImage& image, const LoadedScene& loaded, int size,
                             int spp) const {
        if (size == plan_.image_size) return block_relative_error(image.image, reference_image_.image);
        const ReferenceImage twin = render_reference(loaded, size, spp, 1'000'003ull * spp + 17);
        return block_relative_error(image.image, twin.image) / std::sqrt(2.0);
    }

    // The median time of a frame from a new viewpoint, drawn into a framebuffer of `size`² that exists
    // already (as a viewer's does) and waited for; each frame's camera has moved on a little. The median,
    // since on a shared machine a few frames wait for other work.
    double further_view_seconds(const SceneImageRenderer& renderer, int size, int samples,
                                PixelFormat format) const {
        const OffscreenTarget target(size, size, samples, format);
        Camera moved = camera_;
        renderer.draw_frame(moved, target);  // the first draw into a new framebuffer pays for setting it up
        std::vector<double> seconds;
        for (int frame = 0; frame < plan_.further_view_frames; ++frame) {
            moved.eye += 0.01 * (camera_.target - camera_.eye);
            const auto start = std::chrono::steady_clock::now();
            renderer.draw_frame(moved, target);
            seconds.push_back(seconds_since(start));
        }
        const auto middle = seconds.begin() + static_cast<std::ptrdiff_t>(seconds.size() / 2);
        std::nth_element(seconds.begin(), middle, seconds.end());
        return *middle;
    }

    void compare_with_path_tracer(const RadiosityPipeline& pipeline, const BenchRow& row) {
        int spp = 8;
        for (int size : plan_.comparison_sizes) {
            PathTracerComparison c;
            c.scene = scene_;
            c.image_size = size;
            c.radiosity_image_error = row.image_error;
            const SceneImageRenderer renderer(pipeline, false);
            const auto start = std::chrono::steady_clock::now();
            renderer.render(camera_, size, size);
            c.radiosity_first_seconds = row.seconds() + row.display_seconds + seconds_since(start);
            // The viewer's window: 8-bit sRGB, one sample per pixel (glfw_window.cpp).
            c.radiosity_further_seconds = further_view_seconds(renderer, size, 1, PixelFormat::display_srgb8);
            c.radiosity_further_float_seconds =
                further_view_seconds(renderer, size, 4, PixelFormat::radiance);
            const auto measure = [&](int paths) {
                const ReferenceImage image = render_reference(pipeline.loaded(), size, paths, paths);
                const double error = path_tracer_error(image, pipeline.loaded(), size, paths);
                log_(format("path tracer at %.0f²: ", size) + std::to_string(paths) +
                     format(" spp, %.2f s, ", image.stats.seconds) +
                     format("image error %.2f %%", 100 * error));
                return PathTracerSample{paths, image.stats.seconds, error};
            };
            c.path_tracer =
                find_path_tracer_spp(measure, c.radiosity_image_error, spp, plan_.comparison_max_spp);
            // A larger image needs about as many paths per pixel: start the next search near.
            if (c.path_tracer.found) spp = c.path_tracer.reached.spp;
            results_.comparisons.push_back(c);
        }
    }

    std::string scene_;
    const BenchPlan& plan_;
    BenchResults& results_;
    const std::function<void(const std::string&)>& log_;
    double default_size_ = 0.0;
    Camera camera_;
    ReferenceImage reference_image_;
    Image last_image_;  // of the last run
};

}  // namespace

std::string estimator_label(const EstimatorSetting& setting) {
    return std::string(setting.method == FormFactorMethod::analytic ? "analytic " : "hemisphere ") +
           std::to_string(setting.rays);
}

void run_bench_scene(const std::string& scene, const BenchPlan& plan, BenchResults& results,
                     const std::function<void(const std::string&)>& log) {
    SceneSweep(scene, plan, results, log).run();
}

}  // namespace rad
