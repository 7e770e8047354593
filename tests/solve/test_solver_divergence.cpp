// Systems that cannot converge are reported with a status, never a crash, a hang, NaN or infinity; options
// out of range are refused with the option's name.
#include <gtest/gtest.h>

#include "rad/util/error.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

class StoppingEveryMethod : public ::testing::TestWithParam<SolverMethod> {};

std::string method_test_name(const ::testing::TestParamInfo<SolverMethod>& info) {
    std::string name(solver_method_name(info.param));
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

void expect_stopped_cleanly(Solver& solver, const UniformTransport& system) {
    const StepReport report = test::run_to_end(solver, 1'000'000);
    EXPECT_TRUE(report.status == SolverStatus::not_converging || report.status == SolverStatus::diverged)
        << solver_status_name(report.status);
    EXPECT_FALSE(solver.status_message().empty());
    EXPECT_TRUE(std::isfinite(report.residual));
    EXPECT_TRUE(test::all_finite(solver.solution()));
    EXPECT_TRUE(test::all_finite(solver.display_solution()));
    EXPECT_EQ(solver.solution().size(), system.size());
    const std::size_t steps = report.step;
    EXPECT_EQ(solver.step().step, steps);  // finished: stepping again does nothing
}

// Reflectance 1 in the closed cube (rows summing to exactly 1): the light never decays. Every method says
// so before doing any work.
TEST_P(StoppingEveryMethod, ReflectanceOneInAClosedSceneIsNotConverging) {
    const double f_adjacent = 0.2;
    const UniformTransport system =
        test::unit_cube_system(1.0, glm::dvec3(1.0, 0.0, 0.0), 1.0 - 4 * f_adjacent, f_adjacent);
    auto solver = make_solver(GetParam(), system, SolverOptions{});
    EXPECT_EQ(solver->report().status, SolverStatus::not_converging);
    expect_stopped_cleanly(*solver, system);
    EXPECT_NE(solver->status_message().find("red"), std::string::npos) << solver->status_message();
}

// A closed pair of ρ = 1 mirrors-in-effect (F12 = F21 = 1) beside an open patch: not every row keeps all
// its light, so only running shows the problem (stagnation, growth or breakdown).
TEST_P(StoppingEveryMethod, TrappedLightIsFoundWhileRunning) {
    UniformTransport system;
    system.area = {1.0, 1.0, 1.0};
    system.reflectance = {glm::dvec3(1.0), glm::dvec3(1.0), glm::dvec3(0.5)};
    system.emission = {glm::dvec3(1.0), glm::dvec3(0.0), glm::dvec3(1.0)};
    system.form_factors = test::compress({{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
    auto solver = make_solver(GetParam(), system, SolverOptions{});
    EXPECT_EQ(solver->report().status, SolverStatus::running);
    expect_stopped_cleanly(*solver, system);
}

// ρ = 1.2 on a closed pair: the light grows by 1.2 each bounce.
TEST_P(StoppingEveryMethod, GrowingLightIsReported) {
    UniformTransport system;
    system.area = {1.0, 1.0, 1.0};
    system.reflectance = {glm::dvec3(1.2), glm::dvec3(1.2), glm::dvec3(0.5)};
    system.emission = {glm::dvec3(1.0), glm::dvec3(0.0), glm::dvec3(1.0)};
    system.form_factors = test::compress({{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
    auto solver = make_solver(GetParam(), system, SolverOptions{});
    expect_stopped_cleanly(*solver, system);
}

// Reflectance so large that a step overflows, from either first guess: the solution keeps finite values.
TEST_P(StoppingEveryMethod, OverflowKeepsTheLastFiniteSolution) {
    for (const double huge : {1e150, 1e200}) {
        for (const InitialGuess initial : {InitialGuess::emission, InitialGuess::direct_illumination}) {
            UniformTransport system;
            system.area = {1.0, 1.0, 1.0};
            system.reflectance = {glm::dvec3(huge), glm::dvec3(huge), glm::dvec3(0.0)};
            system.emission = {glm::dvec3(huge), glm::dvec3(0.0), glm::dvec3(1.0)};
            system.form_factors = test::compress({{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}});
            SolverOptions options;
            options.initial = initial;
            auto solver = make_solver(GetParam(), system, options);
            SCOPED_TRACE("huge " + std::to_string(huge) + ", initial " +
                         std::string(initial_guess_name(initial)));
            expect_stopped_cleanly(*solver, system);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Solvers, StoppingEveryMethod, ::testing::ValuesIn(all_solver_methods()),
                         method_test_name);

TEST(SolverOptions, OutOfRangeValuesNameTheirOption) {
    const UniformTransport system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    auto message_of = [&](SolverMethod method, const SolverOptions& options) -> std::string {
        try {
            make_solver(method, system, options);
        } catch (const SettingError& e) {
            return e.setting() + " | " + e.what();
        }
        return "";
    };
    SolverOptions options;
    options.relaxation = 2.0;
    EXPECT_NE(message_of(SolverMethod::gauss_seidel, options)
                  .find("relaxation | relaxation: the over-relaxation factor"),
              std::string::npos);
    options = {};
    options.tolerance = -1.0;
    EXPECT_NE(message_of(SolverMethod::jacobi, options).find("tolerance | tolerance: the relative residual"),
              std::string::npos);
    options = {};
    options.direct_max_dense_patches = 5;
    EXPECT_NE(message_of(SolverMethod::direct, options).find("solver | solver: direct: "), std::string::npos);
    EXPECT_THROW(parse_solver_method("newton"), InputError);
    EXPECT_THROW(parse_initial_guess("zero"), InputError);
    for (SolverMethod m : all_solver_methods()) EXPECT_EQ(parse_solver_method(solver_method_name(m)), m);
}

TEST(SolverInput, MalformedSystemsAreRefused) {
    UniformTransport system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    system.emission[2].y = std::nan("");
    EXPECT_THROW(make_solver(SolverMethod::jacobi, system, SolverOptions{}), std::invalid_argument);
    system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    system.form_factors.column[3] = 6;
    EXPECT_THROW(make_solver(SolverMethod::jacobi, system, SolverOptions{}), std::invalid_argument);
    system = test::unit_cube_system(0.5, glm::dvec3(1.0));
    system.area.pop_back();
    EXPECT_THROW(make_solver(SolverMethod::jacobi, system, SolverOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace rad
