// Jacobi iteration B_{k+1} = E + ρ F B_k. From B_0 = E, B_k = Σ_{m ≤ k} (ρF)^m E: step k holds exactly the
// light of paths of up to k bounces, which is what stepping bounces live shows.
#include "solve/solver_base.hpp"

namespace rad {

namespace {

class JacobiSolver final : public SolverBase {
  public:
    JacobiSolver(const Transport& transport, const SolverOptions& options)
        : SolverBase(SolverMethod::jacobi, transport, options), next_(transport.size()) {
        // next_ = E + ρ F B is both the next iterate and, minus B, the residual of the current one, so each
        // step costs one pass over F and still reports the exact residual of solution().
        jacobi_step(transport_, solution_, next_);
        start(relative_power(power_of_difference(transport_.area, next_, solution_)),
              power_per_channel(transport_.area, solution_));
    }

  private:
    StepOutcome advance() override {
        StepOutcome outcome;
        outcome.unshot_power = power_of_difference(transport_.area, next_, solution_);
        solution_.swap(next_);  // next_ is finite: its residual was
        jacobi_step(transport_, solution_, next_);
        outcome.residual = relative_power(power_of_difference(transport_.area, next_, solution_));
        return outcome;
    }

    std::vector<glm::dvec3> next_;
};

}  // namespace

std::unique_ptr<Solver> make_jacobi_solver(const Transport& transport, const SolverOptions& options) {
    return std::make_unique<JacobiSolver>(transport, options);
}

}  // namespace rad
