#pragma once

#include <cstddef>
#include <string>

#include "rad/solve/solver.hpp"

namespace rad {

// The solver options as the command line takes them: --solver, --tol, --bounces, --initial, --sor.
struct SolverCommandOptions {
    std::string method = "auto";  // auto: recommended_method once the form factors are known
    double tolerance = 1e-5;
    std::size_t bounces = 1000;
    std::string initial = "emission";
    double relaxation = 1.0;
};

// The method named; for "auto", jacobi until the form factors are known (see automatic_method).
SolverMethod solver_method(const SolverCommandOptions& options);
bool automatic_method(const SolverCommandOptions& options);

// The library's options for a scene of `patches` patches. --bounces counts sweeps; a southwell step is one
// shot, so it gets --bounces × patches steps, a sweep's worth of shots per bounce.
SolverOptions solver_options(const SolverCommandOptions& options, std::size_t patches);

}  // namespace rad
