// --solver auto: jacobi, whose steps are bounces, unless the light needs more than half the step limit to
// settle; then cg. The closed cube's rows sum to 1, so q = ρ and jacobi needs ln(tol) / ln(ρ) steps.
#include <gtest/gtest.h>

#include "rad/solve/solver.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

SolverMethod pick(double reflectance, std::size_t max_steps, double tolerance = 1e-5) {
    SolverOptions options;
    options.max_steps = max_steps;
    options.tolerance = tolerance;
    return recommended_method(test::unit_cube_system(reflectance, glm::dvec3(1.0)), options);
}

TEST(RecommendedMethod, JacobiWhileItsBouncesSettleWithinHalfTheLimit) {
    // ln(1e-5) / ln(0.5) = 17 steps; at 0.95, 224 steps: both under 500.
    EXPECT_EQ(pick(0.5, 1000), SolverMethod::jacobi);
    EXPECT_EQ(pick(0.95, 1000), SolverMethod::jacobi);
}

TEST(RecommendedMethod, CgAtHighAlbedo) {
    // 1146 and 11,507 steps against a limit of 1000.
    EXPECT_EQ(pick(0.99, 1000), SolverMethod::conjugate_gradient);
    EXPECT_EQ(pick(0.999, 1000), SolverMethod::conjugate_gradient);
}

TEST(RecommendedMethod, TheLimitAndToleranceDecide) {
    EXPECT_EQ(pick(0.99, 10'000), SolverMethod::jacobi);                   // 1146 < 5000
    EXPECT_EQ(pick(0.95, 400), SolverMethod::conjugate_gradient);          // 224 > 200
    EXPECT_EQ(pick(0.95, 1000, 1e-12), SolverMethod::conjugate_gradient);  // 539 > 500
}

}  // namespace
}  // namespace rad
