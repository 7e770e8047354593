// `radiosity render [SCENE] --out FILE`: solves the scene once and writes the image each camera sees, with no
// window (EGL, or OSMesa). .png gets exposure and the sRGB curve; .exr and .pfm hold linear radiance L = B /
// π. --export writes the mesh drawn (smooth or --flat) with its colours. SCENE may be a saved solution
// (`solve --save`), which is drawn as saved: no form factors, no solve.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/export_option.hpp"
#include "cli/gl_platform_option.hpp"
#include "cli/list_file.hpp"
#include "cli/number_checks.hpp"
#include "cli/solving_options.hpp"
#include "gl/headless_context.hpp"
#include "gl/scene_image_renderer.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/camera/camera_view.hpp"
#include "rad/display/auto_exposure.hpp"
#include "rad/io/image_file.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/reference/image_error.hpp"
#include "rad/reference/path_tracer.hpp"
#include "rad/util/error.hpp"
#include "rad/util/file_names.hpp"
#include "rad/util/stopwatch.hpp"
#include "text/camera_text.hpp"
#include "text/comma_numbers.hpp"
#include "text/progress_bar.hpp"

namespace rad {

namespace {

struct RenderOptions {
    PipelineOptions pipeline;
    std::string out;
    int width = 512;
    int height = 512;
    std::vector<std::string> cameras;  // "ex,ey,ez,tx,ty,tz[,ux,uy,uz]" each; none: the scene's camera
    std::string cameras_file;          // one camera per line
    double fov = 0.0;                  // 0: the camera's own
    Exposure exposure;
    std::vector<std::string> exports;
    bool flat = false;
    bool outline = false;
    HeadlessPlatform gl_platform = HeadlessPlatform::automatic;
    int path_traced = 0;  // paths per pixel of the path tracer's image instead; 0: radiosity's
    std::string compare;  // a reference image to measure the image against
};

// Largest image side: 16384² float RGBA with 4 samples is already 4 GiB of framebuffer.
constexpr int kMaxImageSide = 16384;
// A cameras file is a short list typed by people; more than this is not one (and would be that many images).
constexpr std::size_t kMaxCameras = 10000;
constexpr std::uintmax_t kMaxCamerasFileBytes = 1 << 20;
// More paths per pixel than a reference needs (its noise falls as 1/√n) would run for days.
constexpr int kMaxPathsPerPixel = 1 << 20;

// One camera per line; blank lines and # comments are skipped. Errors name the file and line.
std::vector<Camera> read_cameras_file(const std::string& path, const Camera& fallback) {
    std::vector<Camera> cameras;
    read_list_file(
        path, "--cameras", kMaxCamerasFileBytes, "1 MiB", "a cameras file holds one camera per line",
        [&](std::string_view line, const std::string& where) {
            if (cameras.size() == kMaxCameras) {
                throw InputError(where + ": more than " + std::to_string(kMaxCameras) + " cameras");
            }
            cameras.push_back(parse_camera(std::string(line), fallback, where));
        });
    if (cameras.empty()) throw InputError(path + ": no cameras (one ex,ey,ez,tx,ty,tz[,ux,uy,uz] per line)");
    return cameras;
}

// The cameras asked for, or the scene's own; --fov applies to each.
std::vector<Camera> chosen_cameras(const RenderOptions& options, const Camera& scene) {
    std::vector<Camera> cameras;
    for (const std::string& text : options.cameras) cameras.push_back(parse_camera(text, scene, "--camera"));
    if (!options.cameras_file.empty()) cameras = read_cameras_file(options.cameras_file, scene);
    if (cameras.empty()) cameras.push_back(scene);
    if (options.fov > 0.0)
        for (Camera& camera : cameras) camera.fov_degrees = options.fov;
    return cameras;
}

// out.png, or with several cameras out-1.png, out-2.png, ...: the number before the extension.
std::string image_path(const std::string& out, std::size_t index, std::size_t count) {
    if (count == 1) return out;
    const std::filesystem::path path(out);
    return (path.parent_path() /
            (path.stem().string() + "-" + std::to_string(index + 1) + path.extension().string()))
        .string();
}

// --compare's reference, read before any long work. Errors name the option and the file.
std::optional<Image> read_reference(const RenderOptions& options) {
    if (options.compare.empty()) return std::nullopt;
    if (lowercase_extension(options.compare) != ".pfm") {
        throw InputError("--compare: " + options.compare + ": a reference must be a .pfm (linear radiance)");
    }
    Image reference;
    try {
        reference = read_image(options.compare);
    } catch (const InputError& e) {
        throw InputError(std::string("--compare: ") + e.what());
    }
    if (reference.width != options.width || reference.height != options.height) {
        throw InputError("--compare: " + options.compare + " is " + std::to_string(reference.width) + "x" +
                         std::to_string(reference.height) + ", the images are " +
                         std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " (--width, --height)");
    }
    return reference;
}

// "PATH against REF: X % per 8 x 8 block, Y % per pixel".
std::string comparison(const std::string& path, const Image& image, const Image& reference,
                       const std::string& reference_path) {
    char line[64];
    std::snprintf(line, sizeof line, ": %.2f %% per 8 x 8 block, %.2f %% per pixel",
                  100.0 * block_relative_error(image, reference),
                  100.0 * block_relative_error(image, reference, {.block_size = 1}));
    return path + " against " + reference_path + line;
}

// --path-traced: the path tracer's image from each camera, over the same geometry, instead of radiosity's.
int write_path_traced(const RenderOptions& options, const RadiosityPipeline& pipeline,
                      const std::vector<Camera>& cameras, const std::optional<Image>& reference) {
    const PathTracer tracer(pipeline.loaded().scene, pipeline.patches(),
                            {.seed = options.pipeline.form_factors.seed});
    for (std::size_t k = 0; k < cameras.size(); ++k) {
        ReferenceImage traced;
        {
            Progress progress;
            const ProgressBar bar(progress);
            traced = tracer.render(cameras[k], options.width, options.height, options.path_traced, &progress);
        }
        const std::string path = image_path(options.out, k, cameras.size());
        const double exposure = options.exposure.for_image(auto_exposure(traced.image));
        write_image(path, traced.image, exposure);
        std::printf(
            "wrote %s (%dx%d, path traced: %d paths per pixel, %.1f s; its own noise %.2f %% per 8 x 8 "
            "block, %.2f %% per pixel)\n",
            path.c_str(), options.width, options.height, options.path_traced, traced.stats.seconds,
            100.0 * block_relative_noise(traced.image, traced.standard_error),
            100.0 * block_relative_noise(traced.image, traced.standard_error, {.block_size = 1}));
        if (reference)
            std::printf("%s\n", comparison(path, traced.image, *reference, options.compare).c_str());
    }
    return 0;
}

int run_render(RenderOptions options, const CLI::App& command) {
    check_image_path(options.out);
    check_export_paths(options.exports);
    if (!options.cameras.empty() && !options.cameras_file.empty()) {
        throw InputError("--cameras: give --camera or --cameras, not both");
    }
    options.pipeline.display.mode = options.flat ? ColourMode::flat : ColourMode::smooth;
    const std::string& scene = options.pipeline.scene.scene;
    const bool saved = is_saved_solution_path(scene);
    if (saved) refuse_solving_options(command, scene);
    if (options.path_traced > 0 && !options.exports.empty()) {
        throw InputError("--export: writes radiosity's mesh; not with --path-traced");
    }
    const std::optional<Image> reference = read_reference(options);

    const Stopwatch load_clock;
    std::unique_ptr<RadiosityPipeline> pipeline =
        saved
            ? std::make_unique<RadiosityPipeline>(read_saved_solution(scene), scene, options.pipeline.display)
            : std::make_unique<RadiosityPipeline>(options.pipeline);
    const double load_seconds = load_clock.seconds();
    const std::vector<Camera> cameras = chosen_cameras(options, scene_camera(pipeline->loaded().scene));
    if (options.path_traced > 0) return write_path_traced(options, *pipeline, cameras, reference);

    // A saved solution is drawn as saved; a scene is solved once for every camera.
    if (!pipeline->has_solution()) {
        Progress progress;
        const ProgressBar bar(progress);
        pipeline->solve(&progress);
    }
    const SolutionReport& report = pipeline->solution().report;
    if (report.status == solver_status_name(SolverStatus::diverged) ||
        report.status == solver_status_name(SolverStatus::not_converging)) {
        std::cerr << "radiosity: failed: the solver " << report.status << ": " << report.status_message
                  << '\n';
        return 1;
    }
    const Stopwatch render_clock;
    {
        Progress progress;
        const ProgressBar bar(progress);
        pipeline->prepare_display(&progress);
    }
    const HeadlessContext context(options.gl_platform);
    const SceneImageRenderer renderer(*pipeline, options.outline);
    // Each image is written as soon as it is drawn, so many cameras never hold many images. Exports take
    // the first image's exposure.
    std::vector<double> exposures(cameras.size(), 0.0);
    std::vector<std::string> comparisons;
    for (std::size_t k = 0; k < cameras.size(); ++k) {
        const Image image = renderer.render(cameras[k], options.width, options.height);
        const std::string path = image_path(options.out, k, cameras.size());
        exposures[k] = options.exposure.for_image(auto_exposure(image));
        write_image(path, image, exposures[k]);
        if (reference) comparisons.push_back(comparison(path, image, *reference, options.compare));
    }
    const double render_seconds = render_clock.seconds();

    const std::string& method = pipeline->solution().settings.solver;
    if (saved) {
        std::printf(
            "%zu patches, saved solution of %s (%s: %zu steps, residual %.3g); seconds: load %.3f, "
            "render %.3f (%s)\n",
            pipeline->patches().size(), pipeline->loaded().scene.source.c_str(), method.c_str(), report.steps,
            report.residual, load_seconds, render_seconds, context.description().c_str());
    } else {
        const StageSeconds& s = pipeline->seconds();
        std::printf(
            "%zu patches, %s: %zu steps, residual %.3g; seconds: mesh %.3f, form factors %.3f, solve %.3f, "
            "render %.3f (%s)\n",
            pipeline->patches().size(), method.c_str(), report.steps, report.residual, s.mesh, s.form_factors,
            s.solve, render_seconds, context.description().c_str());
    }
    const bool png = lowercase_extension(options.out) == ".png";
    for (std::size_t k = 0; k < cameras.size(); ++k) {
        std::printf("wrote %s (%dx%d", image_path(options.out, k, cameras.size()).c_str(), options.width,
                    options.height);
        if (png)
            std::printf(", exposure %+.2f EV%s", exposures[k], options.exposure.automatic ? " auto" : "");
        std::printf(")\n");
    }
    for (const std::string& line : comparisons) std::printf("%s\n", line.c_str());
    write_exports(options.exports, *pipeline, exposures.front(), std::cout);
    return 0;
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* render = app.add_subcommand(
        "render",
        "Solve SCENE (or take a saved .radiosity solution) and write the image each camera "
        "sees (no window)");
    add_pipeline_options(*render, options->pipeline);
    render
        ->add_option("--out", options->out,
                     "Image to write: .png (exposure, sRGB), .exr or .pfm (linear radiance)")
        ->required();
    render->add_option("--width", options->width, "Image width in pixels")
        ->check(CLI::Range(1, kMaxImageSide))
        ->capture_default_str();
    render->add_option("--height", options->height, "Image height in pixels")
        ->check(CLI::Range(1, kMaxImageSide))
        ->capture_default_str();
    render
        ->add_option("--camera", options->cameras,
                     "ex,ey,ez,tx,ty,tz[,ux,uy,uz]: eye, target and up (default: the scene's camera, or one "
                     "that frames the scene); repeatable: one image per camera, OUT numbered -1, -2, ...")
        ->allow_extra_args(false);
    render->add_option("--cameras", options->cameras_file,
                       "A file of cameras, one ex,ey,ez,tx,ty,tz[,ux,uy,uz] per line (# comments): one image "
                       "per camera, from one solve");
    render->add_option("--fov", options->fov, "Vertical field of view in degrees (default: the camera's own)")
        ->check(finite_range(1.0, 179.0));
    add_exposure_option(*render, options->exposure,
                        "PNG and --export colours: radiance x 2^EV before sRGB; auto (the default) picks the "
                        "EV that maps the image's log-average luminance to 0.18 grey");
    add_export_option(*render, options->exports);
    render->add_flag("--flat", options->flat, "Show each patch's own radiosity instead of interpolating");
    render->add_flag("--outline", options->outline, "Draw the patches' edges");
    const std::map<std::string, FinalGather> gathers{{"auto", FinalGather::automatic},
                                                     {"near", FinalGather::near},
                                                     {"on", FinalGather::on},
                                                     {"off", FinalGather::off}};
    render
        ->add_option(
            "--final-gather", options->pipeline.display.final_gather,
            "The last bounce gathered by rays, for light that varies across a patch: auto (the "
            "default) or near: the vertices within two patch sizes of a face at least a patch across, "
            "1024 rays each (corners and contact, where patches blur); hierarchical and clustered "
            "solutions are drawn on patches of the uniform size that first gather their own last bounce "
            "from the leaves; on: every vertex, 256 rays; off: none")
        ->transform(CLI::CheckedTransformer(gathers, CLI::ignore_case));
    render
        ->add_option(
            "--path-traced", options->path_traced,
            "Write the path tracer's image instead, with this many paths per pixel (no form factors, "
            "no solve): the independent reference radiosity is measured against")
        ->check(CLI::Range(1, kMaxPathsPerPixel));
    render->add_option("--compare", options->compare,
                       "A reference image of the same size (.pfm, linear radiance; e.g. one --path-traced "
                       "wrote): print each image's error against it, per 8 x 8 block and per pixel, in "
                       "luminance (the bench's measures)");
    add_gl_platform_option(*render, options->gl_platform);
    return [render, options]() -> int {
        if (!*render) return -1;
        return run_render(*options, *render);
    };
}

}  // namespace rad
