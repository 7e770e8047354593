#include "rad/solve/solver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rad/transport/uniform/uniform_transport.hpp"
#include "rad/util/error.hpp"
#include "solve/solver_base.hpp"

namespace rad {

void check_solver_options(const SolverOptions& options) {
    if (!(options.tolerance >= 0.0) || !std::isfinite(options.tolerance)) {
        throw SettingError("tolerance", "the relative residual tolerance must be a finite number ≥ 0");
    }
    if (!(options.relaxation > 0.0 && options.relaxation < 2.0)) {
        throw SettingError("relaxation",
                           "the over-relaxation factor must lie in (0, 2), where Gauss-Seidel converges");
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
    throw SettingError("solver", std::string(name) + ": no such solver (available: " + known + ")");
}

std::string_view initial_guess_name(InitialGuess initial) {
    switch (initial) {
        case InitialGuess::emission:
            return "emission";
        case InitialGuess::direct_illumination:
            return "direct";
        case InitialGuess::given:
            return "given";
    }
    return "emission";
}

InitialGuess parse_initial_guess(std::string_view name) {
    if (name == "emission") return InitialGuess::emission;
    if (name == "direct") return InitialGuess::direct_illumination;
    throw SettingError("initial_guess",
                       std::string(name) + ": must be emission (B = E) or direct (B = E + ρFE)");
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

bool needs_matrix(SolverMethod method) {
    return method != SolverMethod::jacobi;
}

void check_solver_supported(SolverMethod method, bool transport_has_matrix) {
    if (!needs_matrix(method) || transport_has_matrix) return;
    throw SettingError("solver", std::string(solver_method_name(method)) +
                                     " needs the form factors as a matrix, and this transport gathers along "
                                     "links; use jacobi, or a uniform or adaptive {subdivision}");
}

SolverMethod recommended_method(const Transport& transport, const SolverOptions& options) {
    const std::vector<double> reach = transport.reach();
    double weighted = 0.0, area = 0.0;
    for (std::size_t i = 0; i < transport.size(); ++i) {
        const glm::dvec3& rho = transport.reflectance[i];
        weighted += transport.area[i] * std::max({rho.x, rho.y, rho.z}) * reach[i];
        area += transport.area[i];
    }
    const double q = area > 0.0 ? weighted / area : 0.0;
    if (!transport.matrix() || !(q > 0.0) || options.tolerance <= 0.0 || options.max_steps == 0)
        return SolverMethod::jacobi;
    if (q >= 1.0) return SolverMethod::conjugate_gradient;
    const double jacobi_steps = std::log(options.tolerance) / std::log(q);
    return jacobi_steps > 0.5 * static_cast<double>(options.max_steps) ? SolverMethod::conjugate_gradient
                                                                       : SolverMethod::jacobi;
}

std::unique_ptr<Solver> make_solver(SolverMethod method, const Transport& transport,
                                    const SolverOptions& options) {
    check_solver_options(options);
    check_solver_supported(method, transport.matrix() != nullptr);
    validate_elements(transport);
    if (const FormFactorMatrix* f = transport.matrix()) validate_form_factor_matrix(*f, transport.size());
    switch (method) {
        case SolverMethod::jacobi:
            return make_jacobi_solver(transport, options);
        case SolverMethod::gauss_seidel:
            return make_gauss_seidel_solver(transport, options);
        case SolverMethod::southwell:
            return make_southwell_solver(transport, options);
        case SolverMethod::conjugate_gradient:
            return make_conjugate_gradient_solver(transport, options);
        case SolverMethod::direct:
            return make_direct_solver(transport, options);
    }
    throw SettingError("solver", "unknown method");
}

const StepReport& run_to_end(Solver& solver, Progress* progress) {
    while (!solver.report().finished()) {
        if (progress && progress->cancelled()) throw Cancelled{};
        solver.step();
        if (progress) progress->advance();
    }
    return solver.report();
}

}  // namespace rad
