#include "rad/solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rad/error.hpp"
#include "solver_base.hpp"

namespace rad {

void check_solver_options(const SolverOptions& options) {
    if (!(options.tolerance >= 0.0) || !std::isfinite(options.tolerance)) {
        throw InputError("--tol: the relative residual tolerance must be a finite number ≥ 0");
    }
    if (!(options.relaxation > 0.0 && options.relaxation < 2.0)) {
        throw InputError(
            "--sor: the over-relaxation factor must lie in (0, 2), where Gauss-Seidel converges");
    }
}

std::string_view solver_method_name(SolverMethod method) {
    switch (method) {
        case SolverMethod::jacobi:
            return "jacobi";
        case SolverMethod::gauss_seidel:
            return "gauss-seidel";
        case SolverMethod::southwell:
            return "southwell";
        case SolverMethod::conjugate_gradient:
            return "cg";
        case SolverMethod::direct:
            return "direct";
    }
    return "unknown";
}

const std::vector<SolverMethod>& all_solver_methods() {
    static const std::vector<SolverMethod> methods = {SolverMethod::jacobi, SolverMethod::gauss_seidel,
                                                      SolverMethod::southwell,
                                                      SolverMethod::conjugate_gradient, SolverMethod::direct};
    return methods;
}

SolverMethod parse_solver_method(std::string_view name) {
    std::string known;
    for (SolverMethod m : all_solver_methods()) {
        if (name == solver_method_name(m)) return m;
        known += (known.empty() ? "" : ", ") + std::string(solver_method_name(m));
    }
    throw InputError("--solver " + std::string(name) + ": no such solver (available: " + known + ")");
}

std::string_view initial_guess_name(InitialGuess initial) {
    return initial == InitialGuess::emission ? "emission" : "direct";
}

InitialGuess parse_initial_guess(std::string_view name) {
    if (name == "emission") return InitialGuess::emission;
    if (name == "direct") return InitialGuess::direct_illumination;
    throw InputError("--initial " + std::string(name) + ": must be emission (B = E) or direct (B = E + ρFE)");
}

std::string_view solver_status_name(SolverStatus status) {
    switch (status) {
        case SolverStatus::running:
            return "running";
        case SolverStatus::converged:
            return "converged";
        case SolverStatus::iteration_limit:
            return "iteration limit";
        case SolverStatus::diverged:
            return "diverged";
        case SolverStatus::not_converging:
            return "not converging";
    }
    return "unknown";
}

SolverMethod recommended_method(const RadiositySystem& system, const SolverOptions& options) {
    const FormFactorMatrix& f = system.form_factors;
    double weighted = 0.0, area = 0.0;
    for (std::size_t i = 0; i < system.size(); ++i) {
        double row_sum = 0.0;
        for (std::uint64_t k = f.row_begin[i]; k < f.row_begin[i + 1]; ++k) row_sum += f.value[k];
        const glm::dvec3& rho = system.reflectance[i];
        weighted += system.area[i] * std::max({rho.x, rho.y, rho.z}) * row_sum;
        area += system.area[i];
    }
    const double q = area > 0.0 ? weighted / area : 0.0;
    if (!(q > 0.0) || options.tolerance <= 0.0 || options.max_steps == 0) return SolverMethod::jacobi;
    if (q >= 1.0) return SolverMethod::conjugate_gradient;
    const double jacobi_steps = std::log(options.tolerance) / std::log(q);
    return jacobi_steps > 0.5 * static_cast<double>(options.max_steps) ? SolverMethod::conjugate_gradient
                                                                       : SolverMethod::jacobi;
}

std::unique_ptr<Solver> make_solver(SolverMethod method, const RadiositySystem& system,
                                    const SolverOptions& options) {
    check_solver_options(options);
    validate_radiosity_system(system);
    switch (method) {
        case SolverMethod::jacobi:
            return make_jacobi_solver(system, options);
        case SolverMethod::gauss_seidel:
            return make_gauss_seidel_solver(system, options);
        case SolverMethod::southwell:
            return make_southwell_solver(system, options);
        case SolverMethod::conjugate_gradient:
            return make_conjugate_gradient_solver(system, options);
        case SolverMethod::direct:
            return make_direct_solver(system, options);
    }
    throw InputError("--solver: unknown method");
}

}  // namespace rad
