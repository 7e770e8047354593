#pragma once

// Radiosity systems with known answers for the solver tests, built by hand: the closed forms of
// docs/analytic.md, and random systems that are exactly reciprocal, closed (rows summing to 1) or open.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad::test {

using DenseMatrix = std::vector<std::vector<double>>;

// Compressed rows of the nonzero entries of a dense matrix, in float as the form-factor code stores them.
inline FormFactorMatrix compress(const DenseMatrix& f) {
    FormFactorMatrix m;
    for (const auto& row : f) {
        for (std::size_t j = 0; j < row.size(); ++j) {
            if (row[j] == 0.0) continue;
            m.column.push_back(static_cast<std::uint32_t>(j));
            m.value.push_back(static_cast<float>(row[j]));
        }
        m.row_begin.push_back(m.column.size());
    }
    return m;
}

inline DenseMatrix expand(const FormFactorMatrix& m) {
    DenseMatrix f(m.rows(), std::vector<double>(m.rows(), 0.0));
    for (std::size_t i = 0; i < m.rows(); ++i) {
        const FormFactorRow row = m.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) f[i][row.columns[k]] += row.values[k];
    }
    return f;
}

// The one-patch-per-face unit cube of docs/analytic.md, faces in builtin:cube's order: top, bottom, left,
// right, back, front. Opposite faces are (0, 1), (2, 3), (4, 5).
inline UniformTransport unit_cube_system(double reflectance, glm::dvec3 top_emission,
                                         double f_opposite = 0.199825, double f_adjacent = 0.200044) {
    DenseMatrix f(6, std::vector<double>(6, f_adjacent));
    for (std::size_t i = 0; i < 6; ++i) {
        f[i][i] = 0.0;
        f[i][i ^ 1] = f_opposite;
    }
    UniformTransport system;
    system.area.assign(6, 1.0);
    system.reflectance.assign(6, glm::dvec3(reflectance));
    system.emission.assign(6, glm::dvec3(0.0));
    system.emission[0] = top_emission;
    system.form_factors = compress(f);
    return system;
}

// Deterministic uniform numbers in [0, 1), the same on every platform.
class Uniform {
  public:
    explicit Uniform(std::uint64_t seed) : state_(seed) {}
    double operator()() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state_ >> 11) * 0x1.0p-53;
    }

  private:
    std::uint64_t state_;
};

struct RandomSystemOptions {
    std::size_t patches = 300;
    double density = 0.3;  // share of pairs that see each other
    bool closed = false;   // rows sum to 1; otherwise each row sums to a value in [0.6, 0.95]
    std::uint64_t seed = 7;
};

// An exactly reciprocal system: areas are powers of two and A_i F_ij = A_j F_ji = G_ij with G symmetric and
// held in float, so the float matrix F = G / A is reciprocal to the last bit. G = D K D for a random sparse
// symmetric K, with D found by symmetric Sinkhorn scaling so that the rows of F sum to their targets.
// Reflectance and emission are left for the caller (all zero here).
inline UniformTransport random_reciprocal_system(const RandomSystemOptions& options) {
    const std::size_t n = options.patches;
    Uniform uniform(options.seed);
    DenseMatrix k(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            // A ring keeps every patch connected to the rest.
            if (j == i + 1 || uniform() < options.density) k[i][j] = k[j][i] = 0.1 + uniform();
        }
    }
    UniformTransport system;
    std::vector<double> target(n);
    for (std::size_t i = 0; i < n; ++i) {
        system.area.push_back(std::ldexp(1.0, static_cast<int>(uniform() * 4.0) - 1));  // 0.5, 1, 2 or 4
        target[i] = system.area[i] * (options.closed ? 1.0 : 0.6 + 0.35 * uniform());
    }
    std::vector<double> d(n, 1.0);
    for (int iteration = 0; iteration < 2000; ++iteration) {
        double worst = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            double kd = 0.0;
            for (std::size_t j = 0; j < n; ++j) kd += k[i][j] * d[j];
            worst = std::max(worst, std::abs(d[i] * kd / target[i] - 1.0));
            d[i] = std::sqrt(d[i] * target[i] / kd);
        }
        if (worst < 1e-12) break;
    }
    DenseMatrix f(n, std::vector<double>(n, 0.0));
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            const float g = static_cast<float>(d[i] * k[i][j] * d[j]);
            f[i][j] = static_cast<double>(g) / system.area[i];
        }
    }
    system.form_factors = compress(f);
    system.reflectance.assign(n, glm::dvec3(0.0));
    system.emission.assign(n, glm::dvec3(0.0));
    return system;
}

// Runs a solver until it finishes, with a guard so a broken stopping rule fails instead of hanging.
inline StepReport run_to_end(Solver& solver, std::size_t guard = 10'000'000) {
    StepReport report = solver.report();
    for (std::size_t k = 0; k < guard && !report.finished(); ++k) report = solver.step();
    return report;
}

// ||a − b|| / ||b|| in the area-weighted power norm Σ A (|r| + |g| + |b|).
inline double relative_difference(std::span<const double> area, std::span<const glm::dvec3> a,
                                  std::span<const glm::dvec3> b) {
    double difference = 0.0, reference = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const glm::dvec3 d = glm::abs(a[i] - b[i]);
        difference += area[i] * (d.x + d.y + d.z);
        const glm::dvec3 r = glm::abs(b[i]);
        reference += area[i] * (r.x + r.y + r.z);
    }
    return difference / reference;
}

inline bool all_finite(std::span<const glm::dvec3> v) {
    return std::all_of(v.begin(), v.end(), [](const glm::dvec3& x) {
        return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z);
    });
}

}  // namespace rad::test
