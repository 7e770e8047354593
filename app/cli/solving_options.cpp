#include "cli/solving_options.hpp"

#include <tbb/global_control.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cli/number_checks.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

// More threads than any machine this runs on has; a larger count is a typo, and TBB would try to honour it.
constexpr std::size_t kMaxThreads = 1024;

// TBB takes its thread limit from a global_control object for as long as the object lives, so the limit
// the command line asked for lives until the process ends.
void limit_threads(std::size_t threads) {
    static std::unique_ptr<tbb::global_control> limit;
    limit.reset();
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
}

std::vector<std::string> method_names() {
    std::vector<std::string> names{"auto"};
    for (SolverMethod m : all_solver_methods()) names.emplace_back(solver_method_name(m));
    return names;
}

// The built-in scenes' names from their list, so the help never leaves one out.
std::string scene_help() {
    std::string names;
    for (const BuiltinSceneInfo& scene : builtin_scenes()) names += scene.name + ", ";
    return "Scene: a .obj (with its .mtl), .ply, .gltf or .glb file, or builtin:NAME (" + names +
           "or furnace-N: a closed room of balls of about N faces, e.g. furnace-100k, furnace-1m, where "
           "B = 2 everywhere); render and view also take a saved solution, FILE.radiosity";
}

std::vector<std::string> subdivision_name_list() {
    std::vector<std::string> names;
    for (Subdivision s : all_subdivisions()) names.emplace_back(subdivision_name(s));
    return names;
}

// The table's methods with what each does and the size of its first patches.
std::string subdivision_help() {
    std::string automatic;
    for (const TransportMethod& m : transport_methods()) {
        if (m.automatic_up_to == 0) continue;
        automatic += (automatic.empty() ? "" : ", ") + std::string(m.name) +
                     (m.automatic_up_to == kAnySize
                          ? " beyond"
                          : " up to " + std::to_string(m.automatic_up_to) + " patches at the uniform size");
    }
    std::string help = "How patches are made: auto (" + automatic + ")";
    for (const TransportMethod& m : transport_methods()) {
        help += ", " + std::string(m.name) + " (" + std::string(m.help);
        if (m.base_patch_scale != 1.0) {
            char scale[32];
            std::snprintf(scale, sizeof scale, "%g", m.base_patch_scale);
            help += std::string("; --patch-size is its first patches' size, by default ") + scale +
                    " times the uniform one";
        }
        help += ")";
    }
    return help;
}

}  // namespace

void add_form_factor_options(CLI::App& command, FormFactorOptions& options) {
    const std::map<std::string, FormFactorMethod> methods = {{"hemisphere", FormFactorMethod::hemisphere},
                                                             {"analytic", FormFactorMethod::analytic}};
    command
        .add_option(
            "--ff", options.method,
            "Form factors: hemisphere (cosine-weighted rays from each patch; cost grows with patches x "
            "rays) or analytic (closed-form point-to-polygon factors times shadow-ray visibility; cost "
            "grows with patches²)")
        ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case))
        ->default_str("hemisphere");
    command
        .add_option("--rays", options.rays,
                    "Rays per patch for hemisphere (default " + std::to_string(kDefaultHemisphereRays) +
                        "; light sources' factors are analytic), shadow rays per pair of patches for "
                        "analytic (default " +
                        std::to_string(kDefaultAnalyticRays) + ")")
        ->check(CLI::PositiveNumber);
    command
        .add_option("--seed", options.seed,
                    "Seed of the form factors' random numbers; the same seed gives the "
                    "same results whatever the number of threads")
        ->capture_default_str();
    command
        .add_option_function<std::size_t>(
            "--threads", [](const std::size_t& threads) { limit_threads(threads); },
            "Threads to use (default: all cores)")
        ->check(CLI::Range(std::size_t{1}, kMaxThreads));
    command
        .add_option(
            "--max-memory", options.max_memory_bytes,
            "Memory budget of the form factors, e.g. 512M or 4G (default: half the machine's memory); "
            "over it, the command stops and names a --patch-size that fits")
        ->transform(CLI::AsSizeValue(false))
        ->check(CLI::PositiveNumber);
    command.add_flag("--reciprocity", options.enforce_reciprocity,
                     "Make the form factors reciprocal (A_i F_ij = A_j F_ji) by averaging each pair");
    command.add_flag("--normalize-rows", options.normalize_rows,
                     "Scale each patch's form factors to sum to exactly 1 (for closed scenes only)");
}

void add_solver_options(CLI::App& command, SolverCommandOptions& options) {
    command
        .add_option(
            "--solver", options.method,
            "Solver: auto (jacobi, or cg when jacobi would need over half of --bounces steps: high albedo), "
            "jacobi (one bounce per step), gauss-seidel, southwell (progressive shooting), cg (conjugate "
            "gradients, for high albedo) or direct (LU, the reference for small scenes)")
        ->check(CLI::IsMember(method_names()))
        ->capture_default_str();
    command
        .add_option("--tol", options.tolerance,
                    "Stop when the relative residual (unaccounted power over emitted power) is at most this")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command
        .add_option("--bounces", options.bounces,
                    "Stop after this many steps (sweeps; for southwell, sweeps' worth of shots) even if not "
                    "converged")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    command
        .add_option("--initial", options.initial,
                    "First guess: emission (B = E) or direct (the direct illumination B = E + ρFE)")
        ->check(CLI::IsMember({"emission", "direct"}))
        ->capture_default_str();
    command
        .add_option("--sor", options.relaxation,
                    "Over-relaxation factor ω for gauss-seidel, in (0, 2); 1 is plain Gauss-Seidel")
        ->capture_default_str();
}

void add_scene_options(CLI::App& command, SceneOptions& options) {
    command.add_option("scene", options.scene, scene_help())->capture_default_str();
    command
        .add_option("--patch-size", options.patch_size,
                    "Largest patch edge, in scene units (default: a sixteenth of the scene's largest extent)")
        ->check(positive_number());
    command.add_option(
        "--sky", options.sky,
        "Light from a sky at infinity, met by every ray that leaves the scene: R,G,B (or L) is a "
        "uniform radiance; overcast,L (or overcast,R,G,B) the CIE overcast sky of that zenith "
        "radiance, +y up; none");
    command.add_option(
        "--sun", options.sun,
        "A distant sun with shadows: X,Y,Z,E (or X,Y,Z,R,G,B), the direction toward it and the "
        "irradiance on a plane facing it; none");
}

void add_subdivision_options(CLI::App& command, SubdivisionOptions& options) {
    command.add_option("--subdivision", options.method, subdivision_help())
        ->check(CLI::IsMember(subdivision_name_list()))
        ->capture_default_str();
    command
        .add_option("--refine-tol", options.tolerance,
                    "adaptive: the relative step between neighbours that splits them (default 0.15); "
                    "hierarchical and clustered: the error a link may leave in its receiver, relative to the "
                    "scene's mean radiosity (default: hierarchical 0.02, clustered 0.05)")
        ->check(positive_number());
    command
        .add_option(
            "--min-patch-size", options.min_patch_size,
            "adaptive, hierarchical and clustered: patches are not split below this edge, in scene "
            "units (default: adaptive, each first patch's longest edge / 8; hierarchical, the largest "
            "base patch edge / 64; clustered, the scene's largest extent / 64)")
        ->check(positive_number());
}

void add_pipeline_options(CLI::App& command, PipelineOptions& options) {
    add_scene_options(command, options.scene);
    add_form_factor_options(command, options.form_factors);
    add_solver_options(command, options.solver);
    add_subdivision_options(command, options.subdivision);
}

void refuse_solving_options(const CLI::App& command, const std::string& saved) {
    // The options' names, from registering them on a scratch command.
    CLI::App scratch;
    PipelineOptions unused;
    add_pipeline_options(scratch, unused);
    for (const CLI::Option* option : scratch.get_options()) {
        const std::string name = option->get_name();
        if (!option->nonpositional()) continue;  // the scene, which is the saved file
        const CLI::Option* given = command.get_option_no_throw(name);
        if (given && given->count() > 0) {
            throw InputError(name + ": only for solving a scene; " + saved +
                             " is solved already (solve the scene again to change it)");
        }
    }
}

}  // namespace rad
