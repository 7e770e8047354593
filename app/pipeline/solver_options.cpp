#include "pipeline/solver_options.hpp"

#include <vector>

namespace rad {

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
