// The furnace: a closed scene of uniform reflectance ρ and uniform emission E has B = E / (1 − ρ) on every
// patch, whatever the mesh (it needs only form-factor rows summing to 1). Every method must find it to 0.1 %
// at ρ = 0.5, 0.9 and 0.99 on the subdivided builtin:cube with its computed form factors, and the power must
// balance: all that is emitted is absorbed, nothing escapes.
#include <gtest/gtest.h>

#include <tuple>

#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

struct MeshedScene {
    Scene scene;
    PatchMesh patches;
    FormFactorMatrix form_factors;
};

// builtin:cube cut into 4 × 4 patches a face (96), hemisphere form factors with rows scaled to sum to 1.
const MeshedScene& subdivided_cube() {
    static const MeshedScene cube = [] {
        MeshedScene m{make_cube(), {}, {}};
        m.patches = build_patches(m.scene, MeshingOptions{.patch_size = 0.25});
        FormFactorOptions form_factors;
        form_factors.normalize_rows = true;
        form_factors.emitting_surfaces = emitting_surfaces(m.scene);
        m.form_factors = compute_form_factors(m.patches, form_factors);
        return m;
    }();
    return cube;
}

UniformTransport furnace(double reflectance, const glm::dvec3& emission) {
    const MeshedScene& cube = subdivided_cube();
    UniformTransport system = make_uniform_transport(cube.scene, cube.patches, cube.form_factors);
    system.reflectance.assign(system.size(), glm::dvec3(reflectance));
    system.emission.assign(system.size(), emission);
    return system;
}

using FurnaceCase = std::tuple<SolverMethod, double>;

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(Furnace, GivesEOverOneMinusRhoOnEveryPatch) {
    const auto [method, rho] = GetParam();
    const glm::dvec3 e(1.0, 0.5, 2.0);
    const UniformTransport system = furnace(rho, e);
    ASSERT_EQ(system.size(), 96u);
    SolverOptions options;
    // A relative residual r bounds the error by about r / (1 − ρ): 1e-7 leaves 1e-5 at ρ = 0.99.
    options.tolerance = 1e-7;
    options.max_steps = 0;
    auto solver = make_solver(method, system, options);
    const StepReport report = test::run_to_end(*solver);
    ASSERT_TRUE(report.converged()) << solver_status_name(report.status) << ": " << solver->status_message();
    const glm::dvec3 expected = e / (1.0 - rho);
    for (std::size_t i = 0; i < system.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(solver->solution()[i][c], expected[c], 1e-3 * expected[c])
                << "patch " << i << " channel " << c;
        }
    }
    const EnergyBalance balance = energy_balance(system, solver->solution());
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(balance.absorbed[c], balance.emitted[c], 1e-4 * balance.emitted[c]) << "channel " << c;
        EXPECT_NEAR(balance.escaped[c], 0.0, 1e-4 * balance.emitted[c]) << "channel " << c;
    }
}

std::string furnace_name(const ::testing::TestParamInfo<FurnaceCase>& info) {
    std::string name(solver_method_name(std::get<0>(info.param)));
    std::replace(name.begin(), name.end(), '-', '_');
    return name + "_rho_" + std::to_string(static_cast<int>(std::round(std::get<1>(info.param) * 100)));
}

INSTANTIATE_TEST_SUITE_P(Solvers, Furnace,
                         ::testing::Combine(::testing::ValuesIn(all_solver_methods()),
                                            ::testing::Values(0.5, 0.9, 0.99)),
                         furnace_name);

// The closed cube lit from the top only: the light is not uniform, and the power still balances, to within
// the sampled form factors' reciprocity error (the balance assumes A_i F_ij = A_j F_ji).
TEST(ClosedScene, PowerBalancesWithComputedFormFactors) {
    const MeshedScene& cube = subdivided_cube();
    const UniformTransport system = make_uniform_transport(cube.scene, cube.patches, cube.form_factors);
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    ASSERT_TRUE(solver->step().converged());
    const EnergyBalance balance = energy_balance(system, solver->solution());
    EXPECT_NEAR(balance.emitted.x, 1.0, 1e-12);  // the top face: area 1, E = 1
    EXPECT_NEAR(balance.absorbed.x, balance.emitted.x, 2e-3);
    EXPECT_NEAR(balance.escaped.x, 0.0, 1e-5);
}

// A closed system with exact reciprocity (synthetic, 150 patches of four sizes), non-uniform light and
// coloured reflectance: emitted = absorbed to rounding.
UniformTransport exact_closed_system(double reflectance) {
    test::RandomSystemOptions random;
    random.patches = 150;
    random.density = 0.5;
    random.closed = true;
    UniformTransport system = test::random_reciprocal_system(random);
    system.reflectance.assign(system.size(), glm::dvec3(reflectance));
    system.emission.assign(system.size(), glm::dvec3(1.0));
    return system;
}

TEST(ClosedScene, PowerBalancesExactlyWithReciprocalFormFactors) {
    UniformTransport system = exact_closed_system(0.5);
    for (std::size_t i = 0; i < system.size(); ++i) {
        system.reflectance[i] = glm::dvec3(0.3 + 0.005 * static_cast<double>(i % 100), 0.9, 0.1);
        system.emission[i] = i % 10 == 0 ? glm::dvec3(3.0, 2.0, 1.0) : glm::dvec3(0.0);
    }
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    ASSERT_TRUE(solver->step().converged());
    const EnergyBalance balance = energy_balance(system, solver->solution());
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(balance.absorbed[c], balance.emitted[c], 1e-6 * balance.emitted[c]) << "channel " << c;
        EXPECT_NEAR(balance.escaped[c], 0.0, 1e-6 * balance.emitted[c]) << "channel " << c;
    }
}

// In a closed, reciprocal scene each Jacobi step adds the power of one more bounce: ρ^k times the emitted.
TEST(FurnaceJacobi, BouncePowerDecaysAsRhoToTheK) {
    const double rho = 0.9;
    const UniformTransport system = exact_closed_system(rho);
    auto solver = make_solver(SolverMethod::jacobi, system, SolverOptions{});
    const double emitted = energy_balance(system, system.emission).emitted.x;
    for (int k = 0; k <= 10; ++k) {
        if (k > 0) solver->step();
        EXPECT_NEAR(solver->report().unshot_power.x, std::pow(rho, k) * emitted, 1e-6 * emitted)
            << "k = " << k;
    }
}

// Southwell's ambient term is exact in a closed, reciprocal furnace: the displayed power Σ A (B + ρ ambient)
// equals the converged Σ A E / (1 − ρ) after any number of shots, while the shot solution starts far below.
TEST(FurnaceSouthwell, AmbientTermMakesTheDisplayedPowerRight) {
    const double rho = 0.9;
    const UniformTransport system = exact_closed_system(rho);
    auto solver = make_solver(SolverMethod::southwell, system, SolverOptions{});
    const double converged_power = energy_balance(system, system.emission).emitted.x / (1.0 - rho);
    for (int shot = 0; shot < 300; ++shot) {
        const std::vector<glm::dvec3> display = solver->display_solution();
        double displayed = 0.0, shot_power = 0.0;
        for (std::size_t i = 0; i < system.size(); ++i) {
            displayed += system.area[i] * display[i].x;
            shot_power += system.area[i] * solver->solution()[i].x;
        }
        ASSERT_NEAR(displayed, converged_power, 1e-6 * converged_power) << "shot " << shot;
        if (shot == 0) {
            EXPECT_LT(shot_power, 0.2 * converged_power);
        }
        solver->step();
    }
}

}  // namespace
}  // namespace rad
