// `radiosity bench [SCENE]`: the speed-against-error sweep. Every radiosity setting is timed and compared
// with the converged solve of its own form factors (solver error), with a path-traced patch reference
// (total error) and with a path-traced image (image error); the path tracer is set beside radiosity's image.
// `--scaling` runs the scaling sweep instead: builtin furnaces from 1k to 1M faces, clustered and uniform;
// `--leaks` the leak suite: closed rooms lit from outside, with every subdivision.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "bench/bench_plan.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_sweep.hpp"
#include "bench/leak_sweep.hpp"
#include "bench/scaling_report.hpp"
#include "bench/scaling_sweep.hpp"
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
    bool scaling = false;
    bool leaks = false;
    std::string leak_dir = LeakPlan{}.folder;
    std::vector<std::string> scaling_faces;  // empty: the plan's
    std::string out_dir = "out/bench";
    HeadlessPlatform gl_platform = HeadlessPlatform::automatic;
};

std::filesystem::path make_out_dir(const std::string& folder) {
    const std::filesystem::path out_dir(folder);
    std::error_code failed;
    std::filesystem::create_directories(out_dir, failed);
    if (failed || !std::filesystem::is_directory(out_dir)) {
        throw InputError("--out-dir " + folder + ": cannot create the folder (" + failed.message() + ")");
    }
    return out_dir;
}

// No OpenGL: the scaling sweep renders nothing. The report is rewritten after every run, so a sweep stopped
// at a large size keeps the sizes it finished.
int run_scaling_bench(const BenchOptions& options) {
    ScalingPlan plan = default_scaling_plan(options.quick);
    if (!options.scaling_faces.empty()) plan.faces = options.scaling_faces;
    check_scaling_plan(plan);
    const std::filesystem::path out_dir = make_out_dir(options.out_dir);
    std::fprintf(stderr, "bench: scaling sweep on %zu furnace sizes\n", plan.faces.size());
    ScalingResults results;
    const auto write_report = [&](const ScalingResults& r) {
        write_file_atomically(out_dir / "bench.md", scaling_table(r));
        write_file_atomically(out_dir / "bench.csv", scaling_csv(r));
    };
    run_scaling(plan, results, write_report,
                [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
    write_report(results);
    const std::string table = scaling_table(results);
    std::fputs(table.c_str(), stdout);
    std::printf("\nwrote bench.md and bench.csv in %s\n", out_dir.string().c_str());
    return 0;
}

int run_leak_bench(const BenchOptions& options) {
    LeakPlan plan;
    plan.folder = options.leak_dir;
    check_leak_plan(plan);
    const std::filesystem::path out_dir = make_out_dir(options.out_dir);
    const HeadlessContext context(options.gl_platform);
    std::fprintf(stderr, "bench: the leak suite from %s; rendering with %s\n", plan.folder.c_str(),
                 context.description().c_str());
    const std::vector<LeakRow> rows =
        run_leaks(plan, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
    const std::string table = leak_table(rows);
    std::fputs(table.c_str(), stdout);
    write_file_atomically(out_dir / "bench.md", table);
    write_file_atomically(out_dir / "bench.csv", leak_csv(rows));
    std::printf("\nwrote bench.md and bench.csv in %s\n", out_dir.string().c_str());
    return 0;
}

int run_bench(const BenchOptions& options) {
    if (options.scaling) return run_scaling_bench(options);
    if (options.leaks) return run_leak_bench(options);
    BenchPlan plan = default_bench_plan(options.quick);
    if (!options.scene.empty()) plan.scenes = {options.scene};
    const std::filesystem::path out_dir = make_out_dir(options.out_dir);

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
        "The scene (default: builtin:cornell, builtin:white-room, a high-albedo closed room, and "
        "builtin:many-lights, 144 small lamps; --quick: the first two)");
    bench->add_flag("--quick", options->quick, "A sweep of seconds, for tests, instead of minutes");
    bench->add_flag(
        "--scaling", options->scaling,
        "Instead: builtin furnaces from 1k to 1M faces solved clustered and (to 100k) uniform, with "
        "time, memory, links and the furnace error per size; --quick: 1k and 2k");
    bench
        ->add_option("--scaling-faces", options->scaling_faces,
                     "With --scaling: the furnace sizes, as builtin:furnace-N spells them (10k,100k,1m)")
        ->delimiter(',');
    bench->add_flag("--leaks", options->leaks,
                    "Instead: the leak suite, closed rooms lit from outside (assets/hard/leak_*.obj), solved "
                    "with every subdivision, with the light found inside each");
    bench->add_option("--leak-dir", options->leak_dir, "With --leaks: the folder of the leak suite's rooms")
        ->capture_default_str();
    bench
        ->add_option("--out-dir", options->out_dir,
                     "Folder for bench.md (the table), bench.csv and bench.svg")
        ->capture_default_str();
    add_gl_platform_option(*bench, options->gl_platform);
    return [bench, options]() -> int {
        if (!*bench) return -1;
        if (!options->scaling && !options->scaling_faces.empty())
            throw InputError("--scaling-faces: only with --scaling");
        if (options->scaling && options->leaks) throw InputError("--leaks: not with --scaling");
        if (!options->leaks && options->leak_dir != LeakPlan{}.folder)
            throw InputError("--leak-dir: only with --leaks");
        if (options->leaks && !options->scene.empty())
            throw InputError(options->scene + ": the leak suite takes no scene (it solves its own rooms)");
        if (options->scaling && !options->scene.empty())
            throw InputError(options->scene +
                             ": the scaling sweep takes no scene (it solves builtin furnaces)");
        return run_bench(*options);
    };
}

}  // namespace rad
