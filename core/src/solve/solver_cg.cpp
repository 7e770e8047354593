// Conjugate gradients on the symmetric form of the radiosity transport. Multiplying B − ρ F B = E by A/ρ
// gives (A/ρ − A F) B = A E / ρ, and A_i F_ij = A_j F_ji (reciprocity) makes that matrix symmetric; with ρ <
// 1 and rows summing to at most 1 it is diagonally dominant, hence positive definite, which suits high albedo
// where the Jacobi-like methods crawl. Real form factors are reciprocal only approximately, so the solver
// uses for S_ij, off the diagonal, a weighted mean of the pair's two estimates of the exchanged energy,
// S_ij = (A_j · A_i F_ij + A_i · A_j F_ji) / (A_i + A_j), and sets S_ii so that each row keeps its sum
// A_i Σ_j F_ij: the light a patch sends into the scene is unchanged, the matrix stays diagonally dominant,
// and a closed scene keeps its exact furnace answer. The weights are inverse variances: a hemisphere
// estimate of A_i F_ij from N rays has variance about A_i · A_i F_ij / N, so the smaller patch's estimate is
// the better one. For equal areas this is the plain mean; for a tiny patch beside a huge one, whose rays
// find the huge one while the huge one's rays miss it (F_ji = 0), it keeps the tiny patch's estimate
// instead of halving it. CG thus solves the reciprocity-symmetrized system and agrees with the other
// methods to within the form factors' reciprocity error. Patches that do not reflect a channel (ρ = 0) keep
// B = E there and drop out of it. Eigen's ConjugateGradient cannot stop after one iteration and resume, so
// the iteration is written out here; Eigen does the sparse and vector algebra.
#include <Eigen/Dense>

#include "solve/eigen_form_factors.hpp"
#include "solve/solver_base.hpp"

namespace rad {

namespace {

using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using Channels = Eigen::Matrix<double, 1, 3>;

Rows3 to_rows(std::span<const glm::dvec3> v) {
    Rows3 m(static_cast<Eigen::Index>(v.size()), 3);
    for (std::size_t i = 0; i < v.size(); ++i) m.row(static_cast<Eigen::Index>(i)) << v[i].x, v[i].y, v[i].z;
    return m;
}

Eigen::SparseMatrix<double> symmetrized_area_form_factors(const Transport& transport) {
    const auto n = static_cast<Eigen::Index>(transport.size());
    const Eigen::Map<const Eigen::VectorXd> area(transport.area.data(), n);
    Eigen::SparseMatrix<double> area_f = EigenFormFactors(*transport.matrix()).rows().cast<double>();
    area_f = area.asDiagonal() * area_f;
    const Eigen::SparseMatrix<double> transposed = area_f.transpose();
    // (A_j · A_i F_ij + A_i · A_j F_ji) / (A_i + A_j)
    Eigen::SparseMatrix<double> symmetric = area_f * area.asDiagonal();
    symmetric += area.asDiagonal() * transposed;
    for (Eigen::Index j = 0; j < symmetric.outerSize(); ++j) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(symmetric, j); it; ++it) {
            it.valueRef() /= area(it.row()) + area(it.col());
        }
    }
    const Eigen::VectorXd lost_row_sum =
        area_f * Eigen::VectorXd::Ones(n) - symmetric * Eigen::VectorXd::Ones(n);
    Eigen::SparseMatrix<double> diagonal(n, n);
    diagonal.reserve(Eigen::VectorXi::Constant(n, 1));
    for (Eigen::Index i = 0; i < n; ++i) diagonal.insert(i, i) = lost_row_sum(i);
    symmetric += diagonal;
    return symmetric;
}

class ConjugateGradientSolver final : public SolverBase {
  public:
    ConjugateGradientSolver(const Transport& transport, const SolverOptions& options)
        : SolverBase(SolverMethod::conjugate_gradient, transport, options),
          symmetric_(symmetrized_area_form_factors(transport)),
          reflectance_(to_rows(transport.reflectance)),
          x_(to_rows(solution_)) {
        const auto n = static_cast<Eigen::Index>(transport.size());
        const Eigen::VectorXd self = symmetric_.diagonal();
        diagonal_.setZero(n, 3);
        preconditioner_.setZero(n, 3);
        for (Eigen::Index i = 0; i < n; ++i) {
            for (int c = 0; c < 3; ++c) {
                const double rho = reflectance_(i, c);
                if (rho == 0.0) continue;  // B = E there: the unknown is left out
                diagonal_(i, c) = transport.area[static_cast<std::size_t>(i)] / rho;
                // Jacobi preconditioning by the diagonal A/ρ − S_ii, positive whenever ρ Σ_j F_ij < 1; where
                // it is not, A/ρ stands in and the positive-definiteness check will stop the iteration.
                const double pivot = diagonal_(i, c) - self(i);
                preconditioner_(i, c) = 1.0 / (pivot > 0.0 ? pivot : diagonal_(i, c));
            }
        }
        // r = A E / ρ − (A/ρ − S) x on the unknowns; zero where ρ = 0, since x = E there.
        const Rows3 emission = to_rows(transport.emission);
        residual_ = diagonal_.cwiseProduct(emission - x_) + free_part(symmetric_ * x_);
        z_ = preconditioner_.cwiseProduct(residual_);
        direction_ = z_;
        rz_ = residual_.cwiseProduct(z_).colwise().sum();
        start(radiosity_residual(), power_per_channel(transport.area, solution_));
    }

  private:
    StepOutcome advance() override {
        const Rows3 q = diagonal_.cwiseProduct(direction_) - free_part(symmetric_ * direction_);
        const Channels pq = direction_.cwiseProduct(q).colwise().sum();
        Channels alpha = Channels::Zero();
        for (int c = 0; c < 3; ++c) {
            if (rz_(c) == 0.0) continue;  // this channel is solved exactly
            if (!(pq(c) > 0.0)) return not_positive_definite();
            alpha(c) = rz_(c) / pq(c);
        }
        const Rows3 update = direction_ * alpha.asDiagonal();
        const Rows3 x = x_ + update;
        if (!x.allFinite()) return overflow();
        x_ = x;
        residual_ -= q * alpha.asDiagonal();
        z_ = preconditioner_.cwiseProduct(residual_);
        const Channels rz = residual_.cwiseProduct(z_).colwise().sum();
        Channels beta = Channels::Zero();
        for (int c = 0; c < 3; ++c) beta(c) = rz_(c) == 0.0 ? 0.0 : rz(c) / rz_(c);
        rz_ = rz;
        direction_ = z_ + direction_ * beta.asDiagonal();
        for (std::size_t i = 0; i < solution_.size(); ++i) {
            const auto row = static_cast<Eigen::Index>(i);
            solution_[i] = glm::dvec3(x_(row, 0), x_(row, 1), x_(row, 2));
        }
        StepOutcome outcome;
        outcome.residual = radiosity_residual();
        const Eigen::Map<const Eigen::VectorXd> area(transport_.area.data(), update.rows());
        const Channels update_power = area.transpose() * update.cwiseAbs();
        outcome.unshot_power = glm::dvec3(update_power(0), update_power(1), update_power(2));
        return outcome;
    }

    // Rows of the unknowns only: zero where ρ = 0.
    Rows3 free_part(const Rows3& v) const { return (diagonal_.array() > 0.0).select(v, 0.0); }

    // The radiosity residual E + ρFB − B is ρ/A times the symmetric system's, so its power is Σ ρ |r|.
    double radiosity_residual() const {
        const Channels power = reflectance_.cwiseProduct(residual_).cwiseAbs().colwise().sum();
        return relative_power(glm::dvec3(power(0), power(1), power(2)));
    }

    StepOutcome not_positive_definite() const {
        StepOutcome outcome;
        outcome.residual = radiosity_residual();
        outcome.verdict = SolverStatus::not_converging;
        outcome.reason =
            "the symmetric system A/ρ − S is not positive definite (reflectance ≥ 1, or form-factor rows "
            "summing over 1), so conjugate gradients cannot go on";
        return outcome;
    }

    StepOutcome overflow() const {
        StepOutcome outcome;
        outcome.residual = std::numeric_limits<double>::infinity();
        return outcome;
    }

    Eigen::SparseMatrix<double> symmetric_;
    Rows3 reflectance_;
    Rows3 diagonal_;        // A/ρ on the unknowns, 0 where ρ = 0
    Rows3 preconditioner_;  // 1 / (A/ρ − S_ii) on the unknowns
    Rows3 x_;
    Rows3 residual_;
    Rows3 z_;
    Rows3 direction_;
    Channels rz_;
};

}  // namespace

std::unique_ptr<Solver> make_conjugate_gradient_solver(const Transport& transport,
                                                       const SolverOptions& options) {
    return std::make_unique<ConjugateGradientSolver>(transport, options);
}

}  // namespace rad
