// Every solver against the closed-form radiosity solutions of docs/analytic.md, and Jacobi's steps against
// the explicit partial sums of the Neumann series E + ρFE + ... + (ρF)^k E.
#include <gtest/gtest.h>

#include "solver_test_systems.hpp"

namespace rad {
namespace {

using test::DenseMatrix;

class EveryMethod : public ::testing::TestWithParam<SolverMethod> {};

std::string method_test_name(const ::testing::TestParamInfo<SolverMethod>& info) {
    std::string name(solver_method_name(info.param));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

SolverOptions tight() {
    SolverOptions options;
    options.tolerance = 1e-12;
    options.max_steps = 100'000;
    return options;
}

// docs/analytic.md: unit cube, one patch per face, the top emits E = 1, ρ = 0.5 everywhere. The values have
// six decimals, so they are asserted to within 1e-6 (plus float rounding of F).
TEST_P(EveryMethod, UnitCubeOnePatchPerFace) {
    const UniformTransport system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    auto solver = make_solver(GetParam(), system, tight());
    const StepReport report = test::run_to_end(*solver);
    ASSERT_TRUE(report.converged()) << solver->status_message();
    const auto b = solver->solution();
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(b[0][c], 1.090909, 1.5e-6);
        EXPECT_NEAR(b[1][c], 0.181746, 1.5e-6);
        for (int side = 2; side < 6; ++side) EXPECT_NEAR(b[side][c], 0.181836, 1.5e-6) << "side " << side;
    }
}

// docs/analytic.md: two unit squares at distance 1, F12 = F21 = 0.199825, ρ = 0.5, E1 = 1, E2 = 0.
TEST_P(EveryMethod, TwoParallelSquares) {
    UniformTransport system;
    system.area = {1.0, 1.0};
    system.reflectance.assign(2, glm::dvec3(0.5));
    system.emission = {glm::dvec3(1.0), glm::dvec3(0.0)};
    system.form_factors = test::compress({{0.0, 0.199825}, {0.199825, 0.0}});
    auto solver = make_solver(GetParam(), system, tight());
    ASSERT_TRUE(test::run_to_end(*solver).converged()) << solver->status_message();
    EXPECT_NEAR(solver->solution()[0].x, 1.010083, 1e-6);
    EXPECT_NEAR(solver->solution()[1].x, 0.100920, 1e-6);
}

// The two-patch closed form B1 = (E1 + ρ1 F12 E2) / (1 − ρ1 ρ2 F12 F21) with unequal areas and per-channel
// reflectances (one of them zero), which exercises reciprocity and channel independence.
TEST_P(EveryMethod, TwoPatchClosedFormPerChannel) {
    const double a1 = 2.0, a2 = 0.5, f12 = 0.125;  // exact in float
    const double f21 = a1 * f12 / a2;              // reciprocity: 0.5
    const glm::dvec3 rho1(0.8, 0.3, 0.0), rho2(0.6, 0.9, 0.7);
    const glm::dvec3 e1(1.0, 2.0, 3.0), e2(0.5, 0.0, 1.0);
    UniformTransport system;
    system.area = {a1, a2};
    system.reflectance = {rho1, rho2};
    system.emission = {e1, e2};
    system.form_factors = test::compress({{0.0, f12}, {f21, 0.0}});
    auto solver = make_solver(GetParam(), system, tight());
    ASSERT_TRUE(test::run_to_end(*solver).converged()) << solver->status_message();
    const glm::dvec3 b1 = (e1 + rho1 * f12 * e2) / (1.0 - rho1 * rho2 * f12 * f21);
    const glm::dvec3 b2 = (e2 + rho2 * f21 * e1) / (1.0 - rho1 * rho2 * f12 * f21);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(solver->solution()[0][c], b1[c], 1e-9 * b1[c]) << "channel " << c;
        EXPECT_NEAR(solver->solution()[1][c], b2[c], 1e-9 * b2[c]) << "channel " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Solvers, EveryMethod, ::testing::ValuesIn(all_solver_methods()), method_test_name);

// Jacobi from B = E: step k equals Σ_{m=0..k} (ρF)^m E, computed here with explicit dense products.
TEST(Jacobi, StepKIsTheKBouncePartialSum) {
    test::RandomSystemOptions random;
    random.patches = 40;
    UniformTransport system = test::random_reciprocal_system(random);
    test::Uniform uniform(3);
    for (std::size_t i = 0; i < system.size(); ++i) {
        system.reflectance[i] = glm::dvec3(uniform(), uniform(), 0.9 * uniform());
        if (i % 7 == 0) system.emission[i] = glm::dvec3(1.0 + uniform(), uniform(), 2.0);
    }
    const DenseMatrix f = test::expand(system.form_factors);
    auto solver = make_solver(SolverMethod::jacobi, system, tight());

    std::vector<glm::dvec3> bounce = system.emission;  // (ρF)^k E
    std::vector<glm::dvec3> partial_sum = system.emission;
    for (int k = 0; k <= 8; ++k) {
        if (k > 0) {
            std::vector<glm::dvec3> next(system.size(), glm::dvec3(0.0));
            for (std::size_t i = 0; i < system.size(); ++i) {
                for (std::size_t j = 0; j < system.size(); ++j) next[i] += f[i][j] * bounce[j];
                next[i] *= system.reflectance[i];
                partial_sum[i] += next[i];
            }
            bounce = next;
            ASSERT_EQ(solver->step().step, static_cast<std::size_t>(k));
        }
        EXPECT_LT(test::relative_difference(system.area, solver->solution(), partial_sum), 1e-13)
            << "k = " << k;
        // The power of the update is the power of the newest bounce (every entry is non-negative).
        double bounce_power = 0.0;
        for (std::size_t i = 0; i < system.size(); ++i) {
            bounce_power += system.area[i] * (bounce[i].x + bounce[i].y + bounce[i].z);
        }
        const glm::dvec3 unshot = solver->report().unshot_power;
        EXPECT_NEAR(unshot.x + unshot.y + unshot.z, bounce_power, 1e-12 * bounce_power) << "k = " << k;
    }
}

// --bounces stops Jacobi at exactly that many bounces, with a status saying so.
TEST(Jacobi, StopsAtTheStepLimit) {
    const UniformTransport system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    SolverOptions options = tight();
    options.max_steps = 3;
    auto solver = make_solver(SolverMethod::jacobi, system, options);
    const StepReport report = test::run_to_end(*solver);
    EXPECT_EQ(report.status, SolverStatus::iteration_limit);
    EXPECT_EQ(report.step, 3u);
    EXPECT_FALSE(solver->status_message().empty());
    EXPECT_EQ(solver->step().step, 3u);  // finished: further steps do nothing
}

// The direct-illumination first guess is Jacobi's step 1.
TEST(Jacobi, DirectIlluminationStartsOneBounceAhead) {
    const UniformTransport system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    SolverOptions options = tight();
    auto from_emission = make_solver(SolverMethod::jacobi, system, options);
    options.initial = InitialGuess::direct_illumination;
    auto from_direct = make_solver(SolverMethod::jacobi, system, options);
    from_emission->step();
    for (int k = 0; k < 4; ++k) {
        EXPECT_LT(test::relative_difference(system.area, from_direct->solution(), from_emission->solution()),
                  1e-15);
        from_direct->step();
        from_emission->step();
    }
}

}  // namespace
}  // namespace rad
