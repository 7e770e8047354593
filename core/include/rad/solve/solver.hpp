#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "rad/transport/transport.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// How B = E + ρ F B is solved, per RGB channel:
//   jacobi        B_{k+1} = E + ρ F B_k: from B = E, step k holds exactly the light of paths of up to k
//   bounces. gauss_seidel  in-place sweeps, optionally over-relaxed (SOR). southwell     progressive
//   refinement: each step shoots the patch with the most unshot power (ΔB · A). conjugate_gradient
//   preconditioned CG on the symmetric form (A/ρ − S) B = A E / ρ, S_ij = (A_i F_ij +
//                 A_j F_ji) / 2. Real form factors are reciprocal only approximately, so CG solves the
//                 reciprocity-symmetrized system; it matches the others to within the reciprocity error.
//   direct        one step: an Eigen LU of I − ρ F (dense, or sparse for sparse matrices). The reference.
enum class SolverMethod { jacobi, gauss_seidel, southwell, conjugate_gradient, direct };

// The methods' names: jacobi, gauss-seidel, southwell, cg, direct.
std::string_view solver_method_name(SolverMethod method);
const std::vector<SolverMethod>& all_solver_methods();
// Throws SettingError (solver) listing the names.
SolverMethod parse_solver_method(std::string_view name);

// The first guess: B = E, or the direct illumination B = E + ρ F E (the light of paths of up to one bounce),
// or given: SolverOptions::given, a radiosity per element from elsewhere (a saved solution, to continue it).
// Southwell cannot start from a given radiosity (its unshot radiosity is not known): make_solver refuses it.
enum class InitialGuess { emission, direct_illumination, given };
std::string_view initial_guess_name(InitialGuess initial);  // "emission", "direct"
InitialGuess parse_initial_guess(std::string_view name);    // throws SettingError (initial_guess)

// running: more steps will help. iteration_limit: stopped at max_steps before reaching the tolerance.
// diverged: the residual grew a thousandfold, or a step would have produced NaN or infinity.
// not_converging: the light cannot decay (ρ F has spectral radius ≥ 1: reflectance ≥ 1 in a closed scene,
// rows summing over 1), the residual stagnated, or the system is singular or not positive definite.
enum class SolverStatus { running, converged, iteration_limit, diverged, not_converging };
std::string_view solver_status_name(SolverStatus status);  // "running", "converged", "iteration limit", ...

struct SolverOptions {
    double tolerance = 1e-5;       // converged when the relative residual is at most this
    std::size_t max_steps = 1000;  // status iteration_limit after this many steps; 0: no limit
    InitialGuess initial = InitialGuess::emission;
    std::vector<glm::dvec3> given;  // InitialGuess::given: one radiosity per element
    double relaxation = 1.0;        // Gauss-Seidel over-relaxation ω, in (0, 2); 1 is plain Gauss-Seidel
    // Direct solves above these sizes are refused (SettingError, solver): a dense LU costs n³ time
    // and n² memory, a sparse one can fill in just as badly.
    std::size_t direct_max_dense_patches = 6000;
    std::size_t direct_max_sparse_patches = 60000;
};

// What one step did. The residual is relative and measured in power: Σ_i A_i |r_i| (summed over channels)
// over Σ_i A_i E_i, with r = E + ρ F B − B, so it reads as the fraction of the emitted power the solution
// still gets wrong and does not depend on how finely the scene is meshed. (With no emitted power it is the
// absolute Σ A |r|.) It is the residual of solution() for jacobi, cg and direct; gauss-seidel measures the
// iterate before its sweep in the same pass over F (the sweep's result is better still); southwell reports
// its unshot power over the emitted power, which bounds the residual from above.
struct StepReport {
    std::size_t step = 0;  // steps taken so far
    double residual = 0.0;
    // southwell: the power not yet shot, Σ A ΔB. Others: the power of the last update, Σ A |B_k − B_k−1|
    // (for jacobi the power of the newest bounce; at step 0 the emitted power).
    glm::dvec3 unshot_power{0.0};
    SolverStatus status = SolverStatus::running;

    bool converged() const { return status == SolverStatus::converged; }
    bool finished() const { return status != SolverStatus::running; }
};

// A steppable solver; the caller owns the loop:
//     while (!solver->report().finished()) solver->step();
// solution() may be read after any step and never holds NaN or infinity. The solver keeps a reference to
// the system, which must outlive it.
class Solver {
  public:
    virtual ~Solver() = default;

    // One unit of work: a sweep, one shot, one CG iteration, or (direct) the whole solve. Once finished it
    // does nothing and returns the last report.
    virtual StepReport step() = 0;
    virtual const StepReport& report() const = 0;
    // Why the solver stopped, for people; empty while running.
    virtual const std::string& status_message() const = 0;
    virtual SolverMethod method() const = 0;

    // The radiosity B per patch.
    virtual std::span<const glm::dvec3> solution() const = 0;
    // What to show: solution(), plus for southwell the ambient term of Cohen et al. 1988 (ρ times the
    // unshot power spread evenly), so early images are not black.
    virtual std::vector<glm::dvec3> display_solution() const = 0;
};

// Throws SettingError (tolerance, relaxation) for options out of range: callers check before long work.
void check_solver_options(const SolverOptions& options);

// Whether the method reads the form factors themselves (transport.matrix()), not only gather(): all but
// jacobi.
bool needs_matrix(SolverMethod method);
// Throws SettingError (solver) when the method needs a matrix and the transport has none: the one place
// that refuses a method for a transport. make_solver calls it; callers may call it before long work.
void check_solver_supported(SolverMethod method, bool transport_has_matrix);

// What an automatic choice picks: jacobi, whose steps are bounces, unless the light would need more than
// half the step limit to settle and the transport has a matrix, then cg. The jacobi step count is estimated
// from q, the area-weighted mean over elements of ρ (largest channel) × reach: the residual shrinks by about
// q per step, so it needs ln(tolerance) / ln(q) steps. In a closed scene at ρ = 0.999 that is 11,500
// steps; cg needs about 10.
SolverMethod recommended_method(const Transport& transport, const SolverOptions& options);

// Throws SettingError for options out of range (see check_solver_options), a method the transport cannot
// run (check_solver_supported) or a direct solve too large, and std::invalid_argument for malformed
// elements or form factors (see validate_elements). The solver keeps a reference to the transport.
std::unique_ptr<Solver> make_solver(SolverMethod method, const Transport& transport,
                                    const SolverOptions& options);

// Steps the solver until it finishes, advancing `progress` by a step each and throwing Cancelled when it is
// cancelled.
const StepReport& run_to_end(Solver& solver, Progress* progress = nullptr);

}  // namespace rad
