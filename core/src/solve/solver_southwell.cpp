// Progressive refinement (Cohen, Chen, Wallace, Greenberg 1988), i.e. Southwell iteration: each step shoots
// the unshot radiosity ΔB_i of the patch with the most unshot power A_i ΔB_i to every patch j that sees it,
// B_j += ρ_j F_ji ΔB_i (and ΔB_j likewise). Shooting needs F's columns, so the solver keeps a column-major
// copy of F: with F_ji read from the matrix rather than from reciprocity (A_i F_ij / A_j), it solves the
// same system as the other methods even when the form factors are not exactly reciprocal.
#include <glm/common.hpp>

#include "solve/eigen_form_factors.hpp"
#include "solve/solver_base.hpp"

namespace rad {

namespace {

using SparseColumnsF = Eigen::SparseMatrix<float, Eigen::ColMajor, int>;

class SouthwellSolver final : public SolverBase {
  public:
    SouthwellSolver(const Transport& transport, const SolverOptions& options)
        : SolverBase(SolverMethod::southwell, transport, options),
          columns_(EigenFormFactors(*transport.matrix()).rows()),
          unshot_(transport.size()) {
        // The first guess counts as shot: what it holds beyond E + ρF(B − ΔB) is ΔB. From B = E that is E;
        // from the direct illumination E + ρFE it is ρFE.
        for (std::size_t i = 0; i < transport.size(); ++i) {
            unshot_[i] = options.initial == InitialGuess::emission ? transport.emission[i]
                                                                   : solution_[i] - transport.emission[i];
        }
        double total_area = 0.0;
        glm::dvec3 reflected_area(0.0);
        for (std::size_t i = 0; i < transport.size(); ++i) {
            total_area += transport.area[i];
            reflected_area += transport.area[i] * transport.reflectance[i];
        }
        total_area_ = total_area;
        // The overall interreflection factor 1 / (1 − ρ_avg); no ambient estimate where ρ_avg ≥ 1.
        const glm::dvec3 average_reflectance = reflected_area / total_area;
        for (int c = 0; c < 3; ++c) {
            interreflection_[c] = average_reflectance[c] < 1.0 ? 1.0 / (1.0 - average_reflectance[c]) : 0.0;
        }
        find_shooter();
        start(relative_power(unshot_power_), unshot_power_);
    }

    // B + ρ · ambient, ambient = interreflection × unshot power / total area (Cohen et al. 1988, section 5).
    std::vector<glm::dvec3> display_solution() const override {
        const glm::dvec3 ambient = interreflection_ * unshot_power_ / total_area_;
        std::vector<glm::dvec3> display(solution_);
        for (std::size_t i = 0; i < display.size(); ++i) display[i] += transport_.reflectance[i] * ambient;
        return display;
    }

  private:
    // A full sweep's worth of shots must lower the unshot power by 0.1 % unless ρF's spectral radius is
    // within about 1e-4 of 1.
    std::size_t stagnation_window() const override {
        return std::max<std::size_t>(100, 10 * transport_.size());
    }

    StepOutcome advance() override {
        const auto i = static_cast<Eigen::Index>(shooter_);
        const glm::dvec3 shot = unshot_[shooter_];
        // Check the whole shot before applying any of it, so an overflow leaves B as it was.
        increments_.clear();
        for (SparseColumnsF::InnerIterator it(columns_, i); it; ++it) {
            const auto j = static_cast<std::size_t>(it.row());
            increments_.push_back(transport_.reflectance[j] * static_cast<double>(it.value()) * shot);
            if (!is_finite(increments_.back() + solution_[j])) return overflow();
        }
        unshot_[shooter_] = glm::dvec3(0.0);
        std::size_t k = 0;
        for (SparseColumnsF::InnerIterator it(columns_, i); it; ++it, ++k) {
            const auto j = static_cast<std::size_t>(it.row());
            solution_[j] += increments_[k];
            unshot_[j] += increments_[k];
        }
        find_shooter();
        StepOutcome outcome;
        outcome.residual = relative_power(unshot_power_);
        outcome.unshot_power = unshot_power_;
        return outcome;
    }

    StepOutcome overflow() const {
        StepOutcome outcome;
        outcome.residual = std::numeric_limits<double>::infinity();
        return outcome;
    }

    // One pass finds the patch with the most unshot power and sums the unshot power.
    void find_shooter() {
        glm::dvec3 total(0.0);
        double most = -1.0;
        for (std::size_t j = 0; j < unshot_.size(); ++j) {
            const glm::dvec3 power = transport_.area[j] * unshot_[j];
            total += power;
            if (const double sum = power.x + power.y + power.z; sum > most) {
                most = sum;
                shooter_ = j;
            }
        }
        unshot_power_ = total;
    }

    SparseColumnsF columns_;
    std::vector<glm::dvec3> unshot_;
    std::vector<glm::dvec3> increments_;
    std::size_t shooter_ = 0;
    glm::dvec3 unshot_power_{0.0};
    double total_area_ = 0.0;
    glm::dvec3 interreflection_{0.0};
};

}  // namespace

std::unique_ptr<Solver> make_southwell_solver(const Transport& transport, const SolverOptions& options) {
    return std::make_unique<SouthwellSolver>(transport, options);
}

}  // namespace rad
