// Gauss-Seidel sweeps, in place and in patch order, optionally over-relaxed:
// B_i ← B_i + ω (E_i + ρ_i Σ_j F_ij B_j − B_i), using the B_j this sweep has already updated.
#include <cmath>
#include <glm/common.hpp>

#include "solve/solver_base.hpp"

namespace rad {

namespace {

class GaussSeidelSolver final : public SolverBase {
  public:
    GaussSeidelSolver(const Transport& transport, const SolverOptions& options)
        : SolverBase(SolverMethod::gauss_seidel, transport, options), before_(transport.size()) {
        jacobi_step(transport_, solution_, before_);
        start(relative_power(power_of_difference(transport_.area, before_, solution_)),
              power_per_channel(transport_.area, solution_));
    }

  private:
    // One pass over F does the sweep and, from the copy of B taken before it, the exact residual of that
    // earlier iterate: reporting the residual of the sweep's own result would cost a second pass.
    StepOutcome advance() override {
        const FormFactorMatrix& f = matrix();
        const double omega = options_.relaxation;
        before_ = solution_;
        glm::dvec3 residual_power(0.0);
        glm::dvec3 update_power(0.0);
        for (std::size_t i = 0; i < transport_.size(); ++i) {
            glm::dvec3 current(0.0);
            glm::dvec3 earlier(0.0);
            const FormFactorRow row = f.row(i);
            for (std::size_t k = 0; k < row.size(); ++k) {
                const double value = row.values[k];
                current += value * solution_[row.columns[k]];
                earlier += value * before_[row.columns[k]];
            }
            const glm::dvec3 rho = transport_.reflectance[i];
            const glm::dvec3 update = omega * (transport_.emission[i] + rho * current - before_[i]);
            residual_power +=
                transport_.area[i] * glm::abs(transport_.emission[i] + rho * earlier - before_[i]);
            update_power += transport_.area[i] * glm::abs(update);
            solution_[i] = before_[i] + update;
        }
        StepOutcome outcome;
        outcome.residual = relative_power(residual_power);
        outcome.unshot_power = update_power;
        if (!is_finite(update_power)) solution_ = before_;  // SolverBase reports the overflow
        return outcome;
    }

    std::vector<glm::dvec3> before_;
};

}  // namespace

std::unique_ptr<Solver> make_gauss_seidel_solver(const Transport& transport, const SolverOptions& options) {
    return std::make_unique<GaussSeidelSolver>(transport, options);
}

}  // namespace rad
