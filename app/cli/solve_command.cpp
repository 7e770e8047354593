// `radiosity solve [SCENE] --json FILE --save FILE.radiosity`: meshes the scene, computes the form factors,
// runs the chosen solver to convergence (or its step limit), writes the per-patch results and statistics as
// JSON and/or the solved state for render and view (at least one of them), prints a short summary, and with
// --export the display mesh with its colours. Exit status 1 (after writing the JSON and the saved state, and
// exporting nothing) when the system cannot converge.
#include <sys/resource.h>

#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/export_option.hpp"
#include "cli/solving_options.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/io/output_path.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/io/solution_json.hpp"
#include "rad/util/error.hpp"
#include "text/progress_bar.hpp"

namespace rad {

namespace {

struct SolveCommandOptions {
    PipelineOptions pipeline;
    std::string json_path;
    std::string save_path;
    std::vector<std::string> exports;
    double exposure = 0.0;
};

std::size_t peak_memory_bytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

void print_transport(std::ostream& out, const TransportReport& t) {
    char line[512];
    std::snprintf(line, sizeof line, "transport: %s, %zu elements, %zu %s (the nonzeros), %.1f MB, %.3f s\n",
                  t.kind.c_str(), t.elements, t.interactions, t.interaction_name.c_str(),
                  static_cast<double>(t.memory_bytes) / 1e6, t.seconds);
    out << line;
    std::string details;
    for (const TransportDetail& d : t.details) {
        std::snprintf(line, sizeof line, "%s%s %.6g", details.empty() ? "" : ", ", d.name.c_str(), d.value);
        details += line;
    }
    if (!t.notes.empty()) details += (details.empty() ? "" : "; ") + t.notes;
    if (!details.empty()) out << "  " << details << '\n';
}

void print_summary(std::ostream& out, const RadiosityPipeline& pipeline, const SolveStatistics& stats) {
    const LoadedScene& loaded = pipeline.loaded();
    char line[512];
    std::snprintf(line, sizeof line, "scene: %s, %zu patches (%s, patch size %.6g)\n",
                  loaded.scene.source.c_str(), pipeline.patches().size(),
                  std::string(subdivision_name(pipeline.subdivision())).c_str(), loaded.patch_size);
    out << line;
    print_transport(out, stats.transport);
    std::snprintf(line, sizeof line, "solver: %s, %zu steps, relative residual %.3g (tolerance %.3g): %s\n",
                  stats.solver.c_str(), stats.iterations, stats.residual, stats.tolerance,
                  stats.status.c_str());
    out << line;
    std::snprintf(line, sizeof line,
                  "seconds: mesh %.3f, form factors %.3f, solve %.3f; peak memory %.1f MB\n",
                  stats.mesh_seconds, stats.form_factor_seconds, stats.solve_seconds,
                  static_cast<double>(stats.peak_memory_bytes) / 1e6);
    out << line;
    const auto total = [](const glm::dvec3& v) { return v.x + v.y + v.z; };
    std::snprintf(line, sizeof line, "power (sum of channels): emitted %.6g", total(stats.energy.emitted));
    out << line;
    if (total(stats.energy.outside) > 0.0) {
        std::snprintf(line, sizeof line, ", from the sky and sun %.6g", total(stats.energy.outside));
        out << line;
    }
    std::snprintf(line, sizeof line,
                  ", absorbed %.6g (%.6g of it by the backs of one-sided surfaces), escaped %.6g\n",
                  total(stats.energy.absorbed), total(stats.energy.behind), total(stats.energy.escaped));
    out << line;
}

SolveStatistics statistics(const RadiosityPipeline& pipeline) {
    const Solver& solver = pipeline.solver();
    const StepReport& report = solver.report();
    SolveStatistics stats;
    stats.solver = solver_method_name(pipeline.method());
    stats.iterations = report.step;
    stats.residual = report.residual;
    stats.tolerance = pipeline.solver_options().tolerance;
    stats.converged = report.converged();
    stats.status = solver_status_name(report.status);
    stats.status_message = solver.status_message();
    stats.mesh_seconds = pipeline.seconds().mesh;
    stats.form_factor_seconds = pipeline.seconds().form_factors;
    stats.solve_seconds = pipeline.seconds().solve;
    stats.energy = pipeline.energy_balance();
    stats.transport = pipeline.transport().report();
    stats.peak_memory_bytes = peak_memory_bytes();
    return stats;
}

int run_solve(const SolveCommandOptions& options) {
    if (options.json_path.empty() && options.save_path.empty()) {
        throw InputError("solve needs --json FILE or --save FILE.radiosity (or both)");
    }
    if (!options.json_path.empty()) require_output_folder("json_path", options.json_path);
    if (!options.save_path.empty()) {
        if (!is_saved_solution_path(options.save_path)) {
            throw InputError("--save " + options.save_path + ": the name must end in .radiosity");
        }
        require_output_folder("save_path", options.save_path);
    }
    check_export_paths(options.exports);
    if (is_saved_solution_path(options.pipeline.scene.scene)) {
        throw InputError(options.pipeline.scene.scene +
                         ": a saved solution is solved already; solve its scene, or render or view it");
    }
    RadiosityPipeline pipeline(options.pipeline);
    {
        Progress progress;
        const ProgressBar bar(progress);
        pipeline.solve(&progress);
    }
    const SolveStatistics stats = statistics(pipeline);
    const LoadedScene& loaded = pipeline.loaded();
    if (!options.json_path.empty()) {
        write_solution_json(options.json_path, loaded.scene, pipeline.solution(), stats);
    }
    if (!options.save_path.empty()) write_saved_solution(options.save_path, pipeline.saved_solution());

    print_summary(std::cout, pipeline, stats);
    if (!options.json_path.empty()) std::cout << "wrote " << options.json_path << '\n';
    if (!options.save_path.empty()) std::cout << "wrote " << options.save_path << '\n';
    const SolverStatus status = pipeline.solver().report().status;
    if (status == SolverStatus::iteration_limit) {
        std::cerr << "radiosity: warning: " << stats.status_message << '\n';
    }
    if (status == SolverStatus::diverged || status == SolverStatus::not_converging) {
        std::cerr << "radiosity: failed: the solver " << stats.status << ": " << stats.status_message << '\n';
        return 1;  // a failed solution is recorded in the JSON but not exported as colours
    }
    write_exports(options.exports, pipeline, options.exposure, std::cout);
    return 0;
}

}  // namespace

CommandRunner add_solve_command(CLI::App& app) {
    auto options = std::make_shared<SolveCommandOptions>();
    CLI::App* solve = app.add_subcommand(
        "solve", "Solve SCENE's radiosity and write per-patch results as JSON, or the solved state");
    add_pipeline_options(*solve, options->pipeline);
    solve->add_option("--json", options->json_path, "Where to write the per-patch results and statistics");
    solve->add_option("--save", options->save_path,
                      "Where to write the solved state (FILE.radiosity), which render and view show without "
                      "solving again");
    // At least one output, refused while parsing (as a missing --json was before --save existed). Not a
    // CLI11 option group: with one, some unknown short options sent its parser into an endless loop.
    solve->final_callback([options] {
        if (options->json_path.empty() && options->save_path.empty())
            throw CLI::RequiredError("--json or --save");
    });
    add_export_option(*solve, options->exports);
    add_exposure_option(*solve, options->exposure,
                        "--export only: the colours show radiance x 2^EXPOSURE (as render does)");
    return [solve, options]() -> int {
        if (!*solve) return -1;
        return run_solve(*options);
    };
}

}  // namespace rad
