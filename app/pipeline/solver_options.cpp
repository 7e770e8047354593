#include "pipeline/solver_options.hpp"

#include <vector>

namespace rad {

namespace {

std::vector<std::string> method_names() {
    std::vector<std::string> names{"auto"};
    for (SolverMethod m : all_solver_methods()) names.emplace_back(solver_method_name(m));
    return names;
}

}  // namespace

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

SolverMethod solver_method(const SolverCommandOptions& options) {
    return automatic_method(options) ? SolverMethod::jacobi : parse_solver_method(options.method);
}

bool automatic_method(const SolverCommandOptions& options) {
    return options.method == "auto";
}

SolverOptions solver_options(const SolverCommandOptions& options, std::size_t patches) {
    SolverOptions result;
    result.tolerance = options.tolerance;
    result.max_steps = options.bounces;
    if (solver_method(options) == SolverMethod::southwell) result.max_steps = options.bounces * patches;
    result.initial = parse_initial_guess(options.initial);
    result.relaxation = options.relaxation;
    return result;
}

}  // namespace rad
