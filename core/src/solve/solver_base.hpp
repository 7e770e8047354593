#pragma once

// What every solver shares: the stopping rules (tolerance, step limit, growth, stagnation, a system whose
// light cannot decay), the residual in power, and the gather E + ρ F B. Private to the library.

#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"

namespace rad {

// What one unit of work reports to SolverBase. The step must leave solution_ finite: a step that would
// produce NaN or infinity keeps the previous values and reports a non-finite residual.
struct StepOutcome {
    double residual = 0.0;  // relative, see StepReport
    glm::dvec3 unshot_power{0.0};
    std::optional<SolverStatus> verdict;  // the method decided (direct done, CG breakdown)
    std::string reason;                   // why, with the verdict
};

class SolverBase : public Solver {
  public:
    StepReport step() final;
    const StepReport& report() const final { return report_; }
    const std::string& status_message() const final { return message_; }
    SolverMethod method() const final { return method_; }
    std::span<const glm::dvec3> solution() const final { return solution_; }
    std::vector<glm::dvec3> display_solution() const override { return solution_; }

  protected:
    // Puts the initial guess in solution_.
    SolverBase(SolverMethod method, const Transport& transport, const SolverOptions& options);

    // The derived constructor calls this once its state is ready: it records step 0 and stops at once when
    // the light cannot decay.
    void start(double residual, const glm::dvec3& unshot_power);
    virtual StepOutcome advance() = 0;
    // Steps over which the residual must fall by at least 0.1 %, or the solver is not converging.
    virtual std::size_t stagnation_window() const { return 100; }

    // Σ A |r| over Σ A E: the relative residual in power, given r per patch (absolute when nothing emits).
    double relative_power(std::span<const glm::dvec3> residual) const;
    double relative_power(const glm::dvec3& power) const {
        return (power.x + power.y + power.z) / emitted_power_;
    }

    // The form factors, for the methods that need them (make_solver checks that there are some).
    const FormFactorMatrix& matrix() const { return *transport_.matrix(); }

    const Transport& transport_;
    const SolverOptions options_;
    std::vector<glm::dvec3> solution_;

  private:
    void finish(SolverStatus status, std::string message);
    void judge(const StepOutcome& outcome);

    SolverMethod method_;
    double emitted_power_ = 1.0;  // Σ A (E_r + E_g + E_b), or 1 when nothing emits
    StepReport report_;
    std::string message_;
    double lowest_residual_ = 0.0;
    double checkpoint_residual_ = 0.0;  // the residual stagnation_window() steps ago
    bool first_guess_overflowed_ = false;
};

// out = E + ρ · gather(B): one Jacobi step of the radiosity equation, on any transport.
void jacobi_step(const Transport& transport, std::span<const glm::dvec3> radiosity,
                 std::span<glm::dvec3> out);

// Σ_i A_i |v_i| per channel.
glm::dvec3 power_per_channel(std::span<const double> area, std::span<const glm::dvec3> v);
glm::dvec3 power_of_difference(std::span<const double> area, std::span<const glm::dvec3> a,
                               std::span<const glm::dvec3> b);

bool all_finite(std::span<const glm::dvec3> v);
bool is_finite(const glm::dvec3& v);

// One factory per method, each in its solver_<method>.cpp.
std::unique_ptr<Solver> make_jacobi_solver(const Transport& transport, const SolverOptions& options);
std::unique_ptr<Solver> make_gauss_seidel_solver(const Transport& transport, const SolverOptions& options);
std::unique_ptr<Solver> make_southwell_solver(const Transport& transport, const SolverOptions& options);
std::unique_ptr<Solver> make_conjugate_gradient_solver(const Transport& transport,
                                                       const SolverOptions& options);
std::unique_ptr<Solver> make_direct_solver(const Transport& transport, const SolverOptions& options);

}  // namespace rad
