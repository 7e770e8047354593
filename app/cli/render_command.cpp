// `radiosity render [SCENE] --out FILE`: solves the scene once and writes the image a camera sees, with no
// window (EGL, or OSMesa). .png gets exposure and the sRGB curve; .exr and .pfm hold linear radiance L = B /
// π. --export writes the mesh drawn (smooth or --flat) with its colours.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/export_option.hpp"
#include "cli/gl_platform_option.hpp"
#include "cli/number_checks.hpp"
#include "gl/headless_context.hpp"
#include "gl/scene_image_renderer.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/camera/camera_view.hpp"
#include "rad/io/image_file.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

struct RenderOptions {
    PipelineOptions pipeline;
    std::string out;
    int width = 512;
    int height = 512;
    std::string camera;  // "ex,ey,ez,tx,ty,tz[,ux,uy,uz]"; empty: the scene's camera
    double fov = 0.0;    // 0: the camera's own
    double exposure = 0.0;
    std::vector<std::string> exports;
    bool flat = false;
    bool outline = false;
    HeadlessPlatform gl_platform = HeadlessPlatform::automatic;
};

// Largest image side: 16384² float RGBA with 4 samples is already 4 GiB of framebuffer.
constexpr int kMaxImageSide = 16384;

glm::dvec3 vec(const std::vector<double>& v, std::size_t at) {
    return {v[at], v[at + 1], v[at + 2]};
}

Camera parse_camera(const std::string& text, const Camera& fallback) {
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        double value = 0.0;
        std::size_t used = 0;
        try {
            value = std::stod(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || !std::isfinite(value)) {
            throw InputError("--camera: '" + item + "' is not a number (want ex,ey,ez,tx,ty,tz[,ux,uy,uz])");
        }
        values.push_back(value);
    }
    if (values.size() != 6 && values.size() != 9) {
        throw InputError("--camera: " + std::to_string(values.size()) +
                         " numbers; want 6 (eye, target) or 9 (eye, target, up)");
    }
    Camera camera = fallback;
    camera.eye = vec(values, 0);
    camera.target = vec(values, 3);
    if (values.size() == 9) camera.up = vec(values, 6);
    if (glm::length(camera.target - camera.eye) == 0.0) throw InputError("--camera: eye and target coincide");
    if (glm::length(glm::cross(camera.target - camera.eye, camera.up)) == 0.0) {
        throw InputError("--camera: the up vector is zero or points along the view direction");
    }
    return camera;
}

int run_render(RenderOptions options) {
    check_image_path(options.out);
    check_export_paths(options.exports);
    options.pipeline.display.mode = options.flat ? ColourMode::flat : ColourMode::smooth;
    RadiosityPipeline pipeline(options.pipeline);
    Camera camera = scene_camera(pipeline.loaded().scene);
    if (!options.camera.empty()) camera = parse_camera(options.camera, camera);
    if (options.fov > 0.0) camera.fov_degrees = options.fov;

    const StepReport& report = pipeline.solve();
    if (report.status == SolverStatus::diverged || report.status == SolverStatus::not_converging) {
        std::cerr << "radiosity: failed: the solver " << solver_status_name(report.status) << ": "
                  << pipeline.solver().status_message() << '\n';
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    const HeadlessContext context(options.gl_platform);
    const Image image =
        SceneImageRenderer(pipeline, options.outline).render(camera, options.width, options.height);
    const double render_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_image(options.out, image, options.exposure);

    const StageSeconds& s = pipeline.seconds();
    std::printf(
        "%zu patches, %s: %zu steps, residual %.3g; seconds: mesh %.3f, form factors %.3f, solve %.3f, "
        "render %.3f (%s)\n",
        pipeline.patches().size(), std::string(solver_method_name(pipeline.method())).c_str(), report.step,
        report.residual, s.mesh, s.form_factors, s.solve, render_seconds, context.description().c_str());
    std::printf("wrote %s (%dx%d)\n", options.out.c_str(), options.width, options.height);
    write_exports(options.exports, pipeline, options.exposure, std::cout);
    return 0;
}

}  // namespace

CommandRunner add_render_command(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* render =
        app.add_subcommand("render", "Solve SCENE and write the image a camera sees (no window)");
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
    render->add_option(
        "--camera", options->camera,
        "ex,ey,ez,tx,ty,tz[,ux,uy,uz]: eye, target and up (default: the scene's camera, or one "
        "that frames the scene)");
    render->add_option("--fov", options->fov, "Vertical field of view in degrees (default: the camera's own)")
        ->check(finite_range(1.0, 179.0));
    add_exposure_option(*render, options->exposure,
                        "PNG and --export colours: multiply radiance by 2^EXPOSURE (before sRGB)");
    add_export_option(*render, options->exports);
    render->add_flag("--flat", options->flat, "Show each patch's own radiosity instead of interpolating");
    render->add_flag("--outline", options->outline, "Draw the patches' edges");
    add_gl_platform_option(*render, options->gl_platform);
    return [render, options]() -> int {
        if (!*render) return -1;
        return run_render(*options);
    };
}

}  // namespace rad
