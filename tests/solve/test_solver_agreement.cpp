// Every iterative method agrees with the direct solve to 1e-6: on builtin:cornell at 356 patches with its
// computed form factors, and on a synthetic open scene with unequal areas, coloured reflectances (some zero)
// and a few emitters; the power balances in both.
#include <gtest/gtest.h>

#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

// builtin:cornell at --patch-size 100 (356 patches). Reciprocity is enforced so that conjugate gradients,
// which solves the reciprocity-symmetrized system, solves the same system as the others.
const UniformTransport& cornell() {
    static const UniformTransport system = [] {
        const Scene scene = make_cornell_box();
        const PatchMesh patches = build_patches(scene, MeshingOptions{.patch_size = 100.0});
        FormFactorOptions form_factors;
        form_factors.enforce_reciprocity = true;
        return make_uniform_transport(scene, patches, compute_form_factors(patches, form_factors));
    }();
    return system;
}

class CornellAgreesWithDirect : public ::testing::TestWithParam<SolverMethod> {};

TEST_P(CornellAgreesWithDirect, ToOnePartInAMillion) {
    ASSERT_EQ(cornell().size(), 356u);
    auto direct = make_solver(SolverMethod::direct, cornell(), SolverOptions{});
    ASSERT_TRUE(direct->step().converged()) << direct->status_message();
    SolverOptions options;
    options.tolerance = 1e-10;
    options.max_steps = 0;
    auto solver = make_solver(GetParam(), cornell(), options);
    const StepReport report = test::run_to_end(*solver);
    ASSERT_TRUE(report.converged()) << solver->status_message();
    EXPECT_LT(test::relative_difference(cornell().area, solver->solution(), direct->solution()), 1e-6);
    for (std::size_t i = 0; i < cornell().size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(solver->solution()[i][c], direct->solution()[i][c], 1e-6 * direct->solution()[i][c])
                << "patch " << i << " channel " << c;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Solvers, CornellAgreesWithDirect,
                         ::testing::Values(SolverMethod::jacobi, SolverMethod::gauss_seidel,
                                           SolverMethod::southwell, SolverMethod::conjugate_gradient),
                         [](const ::testing::TestParamInfo<SolverMethod>& info) {
                             std::string name(solver_method_name(info.param));
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// The Cornell box is open at the front: at convergence what is emitted is absorbed or escapes.
TEST(EnergyBalance, CornellBoxEmittedIsAbsorbedPlusEscaped) {
    auto direct = make_solver(SolverMethod::direct, cornell(), SolverOptions{});
    ASSERT_TRUE(direct->step().converged());
    const EnergyBalance balance = energy_balance(cornell(), direct->solution());
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(balance.escaped[c], 0.05 * balance.emitted[c]);
        EXPECT_NEAR(balance.absorbed[c] + balance.escaped[c], balance.emitted[c], 1e-6 * balance.emitted[c]);
    }
}

// 300 patches, rows summing to 0.6 .. 0.95 (the rest escapes), exactly reciprocal.
const UniformTransport& open_scene() {
    static const UniformTransport system = [] {
        UniformTransport s = test::random_reciprocal_system({});
        test::Uniform uniform(11);
        for (std::size_t i = 0; i < s.size(); ++i) {
            s.reflectance[i] =
                glm::dvec3(0.95 * uniform(), 0.9 * uniform(), i % 5 == 0 ? 0.0 : 0.8 * uniform());
            if (i % 37 == 0) s.emission[i] = glm::dvec3(10.0 * uniform(), 5.0, 1.0 + uniform());
        }
        return s;
    }();
    return system;
}

const std::vector<glm::dvec3>& direct_solution() {
    static const std::vector<glm::dvec3> b = [] {
        auto solver = make_solver(SolverMethod::direct, open_scene(), SolverOptions{});
        const StepReport report = solver->step();
        EXPECT_TRUE(report.converged()) << solver->status_message();
        EXPECT_LT(report.residual, 1e-12);
        return std::vector<glm::dvec3>(solver->solution().begin(), solver->solution().end());
    }();
    return b;
}

struct AgreementCase {
    SolverMethod method;
    InitialGuess initial = InitialGuess::emission;
    double relaxation = 1.0;
    std::string name;
};

class SyntheticAgreesWithDirect : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(SyntheticAgreesWithDirect, ToOnePartInAMillion) {
    const AgreementCase& c = GetParam();
    SolverOptions options;
    options.tolerance = 1e-9;
    options.max_steps = 0;
    options.initial = c.initial;
    options.relaxation = c.relaxation;
    auto solver = make_solver(c.method, open_scene(), options);
    const StepReport report = test::run_to_end(*solver);
    ASSERT_TRUE(report.converged()) << solver->status_message();
    EXPECT_LE(report.residual, 1e-9);
    EXPECT_LT(test::relative_difference(open_scene().area, solver->solution(), direct_solution()), 1e-6);
    for (std::size_t i = 0; i < open_scene().size(); ++i) {
        for (int ch = 0; ch < 3; ++ch) {
            ASSERT_NEAR(solver->solution()[i][ch], direct_solution()[i][ch],
                        1e-6 * direct_solution()[i][ch] + 1e-12)
                << "patch " << i << " channel " << ch;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Solvers, SyntheticAgreesWithDirect,
    ::testing::Values(
        AgreementCase{SolverMethod::jacobi, InitialGuess::emission, 1.0, "jacobi"},
        AgreementCase{SolverMethod::gauss_seidel, InitialGuess::emission, 1.0, "gauss_seidel"},
        AgreementCase{SolverMethod::gauss_seidel, InitialGuess::emission, 1.3, "sor_1_3"},
        AgreementCase{SolverMethod::southwell, InitialGuess::emission, 1.0, "southwell"},
        AgreementCase{SolverMethod::conjugate_gradient, InitialGuess::emission, 1.0, "cg"},
        AgreementCase{SolverMethod::jacobi, InitialGuess::direct_illumination, 1.0, "jacobi_direct"},
        AgreementCase{SolverMethod::southwell, InitialGuess::direct_illumination, 1.0, "southwell_direct"},
        AgreementCase{SolverMethod::conjugate_gradient, InitialGuess::direct_illumination, 1.0, "cg_direct"}),
    [](const ::testing::TestParamInfo<AgreementCase>& info) { return info.param.name; });

TEST(EnergyBalance, SyntheticEmittedIsAbsorbedPlusEscaped) {
    const EnergyBalance balance = energy_balance(open_scene(), direct_solution());
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(balance.escaped[c], 0.05 * balance.emitted[c]);
        EXPECT_NEAR(balance.absorbed[c] + balance.escaped[c], balance.emitted[c], 1e-9 * balance.emitted[c]);
    }
}

// Before convergence the balance does not hold: it measures the light still missing.
TEST(EnergyBalance, FirstGuessIsNotBalanced) {
    const EnergyBalance balance = energy_balance(open_scene(), open_scene().emission);
    EXPECT_GT(balance.imbalance().x, 0.01 * balance.emitted.x);
}

// With no light at all every method stops at once with B = 0.
TEST(NoEmission, EveryMethodConvergesToDarkness) {
    UniformTransport dark = open_scene();
    dark.emission.assign(dark.size(), glm::dvec3(0.0));
    for (SolverMethod method : all_solver_methods()) {
        auto solver = make_solver(method, dark, SolverOptions{});
        const StepReport report = test::run_to_end(*solver, 10);
        EXPECT_TRUE(report.converged()) << solver_method_name(method) << ": " << solver->status_message();
        for (const glm::dvec3& b : solver->solution()) EXPECT_EQ(b, glm::dvec3(0.0));
    }
}

}  // namespace
}  // namespace rad
