// `radiosity bench [SCENE]`: the speed-against-error sweep. Every radiosity setting is timed and compared
// with the converged solve of its own form factors (solver error), with a path-traced patch reference
// (total error) and with a path-traced image (image error); the path tracer is set beside radiosity's image.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "bench/bench_plan.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_sweep.hpp"
#include "cli/commands.hpp"
#include "cli/gl_platform_option.hpp"
#include "gl/headless_context.hpp"
#include "rad/io/atomic_file.hpp"
#include "rad/io/image_file.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

struct BenchOptions {
    std::string scene;  // empty: the plan's scenes
    bool quick = false;
    std::string out_dir = "out/bench";
    HeadlessPlatform gl_platform = HeadlessPlatform::automatic;
};

int run_bench(const BenchOptions& options) {
    BenchPlan plan = default_bench_plan(options.quick);
    if (!options.scene.empty()) plan.scenes = {options.scene};
    const std::filesystem::path out_dir(options.out_dir);
    std::error_code failed;
    std::filesystem::create_directories(out_dir, failed);
    if (failed || !std::filesystem::is_directory(out_dir)) {
        throw InputError("--out-dir " + options.out_dir + ": cannot create the folder (" + failed.message() +
                         ")");
    }

    const HeadlessContext context(options.gl_platform);
    std::fprintf(stderr, "bench: %s sweep on %zu scene(s); rendering with %s\n",
                 options.quick ? "quick" : "full", plan.scenes.size(), context.description().c_str());
    BenchResults results;
    for (const std::string& scene : plan.scenes) {
        run_bench_scene(scene, plan, results,
                        [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
    }
    const std::string table = bench_table(results);
    std::fputs(table.c_str(), stdout);
    write_file_atomically(out_dir / "bench.md", table);
    write_file_atomically(out_dir / "bench.csv", bench_csv(results));
    write_file_atomically(out_dir / "bench.svg", bench_plot_svg(results));
    for (const NamedImage& image : results.images) write_image((out_dir / image.name).string(), image.image);
    std::printf(
        "\nwrote bench.md, bench.csv, bench.svg and %zu images (the first run's and the path tracer's) "
        "in %s\n",
        results.images.size(), out_dir.string().c_str());
    return 0;
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* bench = app.add_subcommand(
        "bench", "Time every solver, form-factor estimator and mesh size against a path-traced reference");
    bench->add_option(
        "scene", options->scene,
        "The scene (default: builtin:cornell and builtin:white-room, a high-albedo closed room)");
    bench->add_flag("--quick", options->quick, "A sweep of seconds, for tests, instead of minutes");
    bench
        ->add_option("--out-dir", options->out_dir,
                     "Folder for bench.md (the table), bench.csv and bench.svg")
        ->capture_default_str();
    add_gl_platform_option(*bench, options->gl_platform);
    return [bench, options]() -> int {
        if (!*bench) return -1;
        return run_bench(*options);
    };
}

}  // namespace rad
