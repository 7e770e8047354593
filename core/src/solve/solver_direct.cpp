// The reference: (I − ρF) B = E solved by Eigen's LU, per channel. Dense partial-pivoting LU when F is dense
// (the usual case: most patches see a good share of the others), sparse LU when it is sparse. Channels with
// the same reflectance on every patch (a grey scene) share one factorization.
#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <algorithm>
#include <array>

#include "rad/util/error.hpp"
#include "solve/eigen_form_factors.hpp"
#include "solve/solver_base.hpp"

namespace rad {

namespace {

// Above this fraction of nonzeros the dense LU wins over the sparse one.
constexpr double kDenseFraction = 0.02;
// The accuracy an LU solve reaches on any system that is not close to singular.
constexpr double kDirectResidual = 1e-8;

using ChannelGroup = std::vector<int>;

bool is_dense(const FormFactorMatrix& f) {
    const auto n = static_cast<double>(f.rows());
    return static_cast<double>(f.nonzeros()) >= kDenseFraction * n * n;
}

// Channels whose reflectance agrees on every patch, so one factorization of I − ρF serves them all.
std::vector<ChannelGroup> channels_sharing_reflectance(const Transport& transport) {
    std::vector<ChannelGroup> groups;
    for (int c = 0; c < 3; ++c) {
        auto same = [&](const ChannelGroup& g) {
            return std::all_of(transport.reflectance.begin(), transport.reflectance.end(),
                               [&](const glm::dvec3& rho) { return rho[c] == rho[g.front()]; });
        };
        auto it = std::find_if(groups.begin(), groups.end(), same);
        if (it == groups.end()) {
            groups.push_back({c});
        } else {
            it->push_back(c);
        }
    }
    return groups;
}

Eigen::VectorXd reflectance_channel(const Transport& transport, int c) {
    Eigen::VectorXd rho(static_cast<Eigen::Index>(transport.size()));
    for (std::size_t i = 0; i < transport.size(); ++i)
        rho(static_cast<Eigen::Index>(i)) = transport.reflectance[i][c];
    return rho;
}

Eigen::MatrixXd emission_columns(const Transport& transport, const ChannelGroup& group) {
    Eigen::MatrixXd e(static_cast<Eigen::Index>(transport.size()), static_cast<Eigen::Index>(group.size()));
    for (std::size_t i = 0; i < transport.size(); ++i) {
        for (std::size_t g = 0; g < group.size(); ++g) {
            e(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(g)) = transport.emission[i][group[g]];
        }
    }
    return e;
}

// B for the channels of `group`, one column each; empty when the factorization fails.
Eigen::MatrixXd solve_dense(const Transport& transport, const ChannelGroup& group) {
    const FormFactorMatrix& f = *transport.matrix();
    const auto n = static_cast<Eigen::Index>(transport.size());
    const Eigen::VectorXd rho = reflectance_channel(transport, group.front());
    Eigen::MatrixXd k = Eigen::MatrixXd::Identity(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const FormFactorRow row = f.row(static_cast<std::size_t>(i));
        for (std::size_t e = 0; e < row.size(); ++e)
            k(i, row.columns[e]) -= rho(i) * static_cast<double>(row.values[e]);
    }
    return Eigen::PartialPivLU<Eigen::MatrixXd>(k).solve(emission_columns(transport, group));
}

Eigen::MatrixXd solve_sparse(const Transport& transport, const ChannelGroup& group) {
    const auto n = static_cast<Eigen::Index>(transport.size());
    const Eigen::VectorXd rho = reflectance_channel(transport, group.front());
    const Eigen::SparseMatrix<double> f = EigenFormFactors(*transport.matrix()).rows().cast<double>();
    Eigen::SparseMatrix<double> identity(n, n);
    identity.setIdentity();
    const Eigen::SparseMatrix<double> k = identity - rho.asDiagonal() * f;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    lu.compute(k);
    if (lu.info() != Eigen::Success) return {};
    return lu.solve(emission_columns(transport, group));
}

class DirectSolver final : public SolverBase {
  public:
    DirectSolver(const Transport& transport, const SolverOptions& options)
        : SolverBase(SolverMethod::direct, transport, options), gathered_(transport.size()) {
        jacobi_step(transport_, solution_, gathered_);
        start(relative_power(power_of_difference(transport_.area, gathered_, solution_)),
              power_per_channel(transport_.area, solution_));
    }

  private:
    StepOutcome advance() override {
        std::vector<glm::dvec3> b(transport_.size());
        for (const ChannelGroup& group : channels_sharing_reflectance(transport_)) {
            const Eigen::MatrixXd x =
                is_dense(matrix()) ? solve_dense(transport_, group) : solve_sparse(transport_, group);
            if (x.rows() != static_cast<Eigen::Index>(b.size()) || !x.allFinite()) return singular();
            for (std::size_t i = 0; i < b.size(); ++i) {
                for (std::size_t g = 0; g < group.size(); ++g) {
                    b[i][group[g]] = x(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(g));
                }
            }
        }
        if (has_negative_radiosity(b)) return light_does_not_decay();
        jacobi_step(transport_, b, gathered_);
        StepOutcome outcome;
        outcome.residual = relative_power(power_of_difference(transport_.area, gathered_, b));
        if (!std::isfinite(outcome.residual) ||
            outcome.residual > std::max(options_.tolerance, kDirectResidual)) {
            return singular();
        }
        outcome.unshot_power = power_of_difference(transport_.area, b, solution_);
        outcome.verdict = SolverStatus::converged;
        outcome.reason = "solved directly (LU)";
        solution_ = std::move(b);
        return outcome;
    }

    StepOutcome singular() const {
        StepOutcome outcome;
        outcome.residual = report().residual;
        outcome.verdict = SolverStatus::not_converging;
        outcome.reason = "I − ρF is singular or nearly so: the light cannot decay (reflectance ≥ 1?)";
        return outcome;
    }

    // I − ρF with ρF ≥ 0 has a non-negative inverse exactly when ρF's spectral radius is below 1 (it is
    // then an M-matrix), so a negative radiosity from non-negative emission means the light of the bounces
    // grows rather than decays: the LU found the algebraic solution of a system with no physical one.
    static bool has_negative_radiosity(const std::vector<glm::dvec3>& b) {
        double largest = 0.0, lowest = 0.0;
        for (const glm::dvec3& v : b) {
            largest = std::max({largest, v.x, v.y, v.z});
            lowest = std::min({lowest, v.x, v.y, v.z});
        }
        return lowest < -kDirectResidual * largest;
    }

    StepOutcome light_does_not_decay() const {
        StepOutcome outcome;
        outcome.residual = report().residual;
        outcome.verdict = SolverStatus::not_converging;
        outcome.reason =
            "the solution of I − ρF has negative radiosity: ρF has spectral radius above 1, so the light of "
            "each bounce grows (reflectance ≥ 1, or form-factor rows summing over 1)";
        return outcome;
    }

    std::vector<glm::dvec3> gathered_;
};

}  // namespace

std::unique_ptr<Solver> make_direct_solver(const Transport& transport, const SolverOptions& options) {
    const bool dense = is_dense(*transport.matrix());
    const std::size_t limit = dense ? options.direct_max_dense_patches : options.direct_max_sparse_patches;
    if (transport.size() > limit) {
        throw SettingError("solver", "direct: " + std::to_string(transport.size()) +
                                         " patches are too many for a " + (dense ? "dense" : "sparse") +
                                         " direct solve (at most " + std::to_string(limit) +
                                         "); use cg or gauss-seidel, or a larger {patch_size}");
    }
    return std::make_unique<DirectSolver>(transport, options);
}

}  // namespace rad
