// Hard cases about how much light there is: an open scene (light escapes, and the escape is reported), no
// emitter at all (an all-zero answer, not 0 / 0), emitters of 1e6 beside reflectances of 1e-6 (no overflow,
// no underflow to zero or NaN), and the form factors' float storage (the solution agrees with one computed
// from the same factors in double).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "form_factor_test_scenes.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "solver_test_systems.hpp"
#include "test_support.hpp"
#include "transport/uniform/form_factors_analytic.hpp"

namespace rad {
namespace {

std::string asset(const std::string& name) {
    return std::string(RAD_SOURCE_DIR) + "/assets/hard/" + name;
}

nlohmann::json solve_json(const std::vector<std::string>& args, test::CommandResult* result = nullptr) {
    test::TempDir dir;
    const std::string json = (dir.path() / "solution.json").string();
    std::vector<std::string> all{"solve"};
    all.insert(all.end(), args.begin(), args.end());
    all.insert(all.end(), {"--json", json});
    const test::CommandResult r = test::run_radiosity(all);
    if (result) *result = r;
    EXPECT_EQ(r.status, 0) << r.err;
    std::ifstream in(json);
    return nlohmann::json::parse(in);
}

// assets/hard/open_plates.obj at one patch per plate, analytic factors (F = 0.199825 both ways): the
// solution is the closed form B_lower = E / (1 − (ρF)²), B_upper = ρ F B_lower, and the JSON reports the
// escaped power (1 − F)(A B_lower + A B_upper) = 0.889, with emitted = absorbed + escaped.
TEST(OpenScene, EscapedPowerIsReportedAndTheSolutionIsTheClosedForm) {
    const nlohmann::json doc =
        solve_json({asset("open_plates.obj"), "--patch-size", "1", "--ff", "analytic", "--solver", "direct"});
    const double f = test::parallel_rectangles_factor(1, 1, 1);
    const double rho = 0.5;
    const double lower = 1.0 / (1.0 - rho * rho * f * f);
    const double upper = rho * f * lower;
    const auto& patches = doc.at("patches");
    ASSERT_EQ(patches.size(), 2u);
    for (const auto& p : patches) {
        const double expected = p.at("surface") == "lower" ? lower : upper;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(p.at("radiosity").at(c).get<double>(), expected, 1e-5 * expected);
    }
    const auto& energy = doc.at("stats").at("energy");
    for (int c = 0; c < 3; ++c) {
        const double emitted = energy.at("emitted").at(c).get<double>();
        const double absorbed = energy.at("absorbed").at(c).get<double>();
        const double escaped = energy.at("escaped").at(c).get<double>();
        EXPECT_NEAR(emitted, 1.0, 1e-12);
        EXPECT_NEAR(escaped, (1.0 - f) * (lower + upper), 1e-5);
        EXPECT_NEAR(absorbed, (1.0 - rho) * f * (lower + upper), 1e-5);
        EXPECT_NEAR(emitted, absorbed + escaped, 1e-5);
    }
    std::printf("[ figures  ] open plates: escaped %.6f of emitted 1\n",
                energy.at("escaped").at(0).get<double>());
}

// The same scene finely meshed with the default estimator: the rays that leave report the escape, and the
// power balances to within the sampled factors' reciprocity error.
TEST(OpenScene, TheDefaultEstimatorReportsTheEscapeToo) {
    const nlohmann::json doc = solve_json({asset("open_plates.obj"), "--patch-size", "0.125"});
    const auto& stats = doc.at("stats");
    EXPECT_TRUE(stats.at("converged").get<bool>());
    EXPECT_GT(stats.at("transport").at("escaped_ray_fraction").get<double>(), 0.7);
    const auto& energy = stats.at("energy");
    const double emitted = energy.at("emitted").at(0).get<double>();
    const double escaped = energy.at("escaped").at(0).get<double>();
    EXPECT_NEAR(escaped, 0.889, 0.005);
    EXPECT_NEAR(emitted, energy.at("absorbed").at(0).get<double>() + escaped, 5e-3 * emitted);
}

// builtin:many-lights, the open Cornell box lit by 144 lamps whose backs face the ceiling: emitted = absorbed
// + escaped within 0.5 % with uniform patches (the lamps' columns drawn by power) and with clustering.
TEST(OpenScene, ManySmallLampsBalanceTheirPower) {
    for (const char* subdivision : {"uniform", "clustered"}) {
        const nlohmann::json doc = solve_json({"builtin:many-lights", "--subdivision", subdivision});
        const auto& energy = doc.at("stats").at("energy");
        const double emitted = energy.at("emitted").at(1).get<double>();
        const double absorbed = energy.at("absorbed").at(1).get<double>();
        const double escaped = energy.at("escaped").at(1).get<double>();
        EXPECT_GT(escaped, 0.1 * emitted) << subdivision;  // the open front
        EXPECT_GT(energy.at("behind").at(1).get<double>(), 0.0) << subdivision;
        EXPECT_NEAR(absorbed + escaped, emitted, 5e-3 * emitted) << subdivision;
        std::printf(
            "[ figures  ] many-lights, %s: emitted %.6g, absorbed %.6g (%.3g by backs), escaped %.6g\n",
            subdivision, emitted, absorbed, energy.at("behind").at(1).get<double>(), escaped);
    }
}

// Closed rooms whose light meets the backs of one-sided surfaces (400 lamps' backs under a ceiling, a panel
// built of two back-to-back faces): no ray leaves, so nothing escapes, with uniform patches, hierarchical
// radiosity or clustering; the light the backs take is absorbed, and reported apart, and what is absorbed is
// what is emitted within 0.5 %.
TEST(ClosedScene, NothingEscapesAndWhatBacksTakeIsAbsorbed) {
    for (const char* name : {"many_lights.obj", "back_to_back.obj"}) {
        for (const char* subdivision : {"clustered", "hierarchical"}) {
            const nlohmann::json linked = solve_json({asset(name), "--subdivision", subdivision});
            const auto& energy = linked.at("stats").at("energy");
            EXPECT_EQ(energy.at("escaped").at(1).get<double>(), 0.0) << name << ", " << subdivision;
            const double emitted = energy.at("emitted").at(1).get<double>();
            EXPECT_NEAR(energy.at("absorbed").at(1).get<double>(), emitted, 5e-3 * emitted)
                << name << ", " << subdivision;
        }
        const nlohmann::json doc = solve_json({asset(name)});
        const auto& stats = doc.at("stats");
        EXPECT_EQ(stats.at("transport").at("escaped_ray_fraction").get<double>(), 0.0) << name;
        const auto& energy = stats.at("energy");
        const double emitted = energy.at("emitted").at(1).get<double>();
        EXPECT_EQ(energy.at("escaped").at(1).get<double>(), 0.0) << name;
        EXPECT_GT(energy.at("behind").at(1).get<double>(), 0.0) << name;
        EXPECT_NEAR(energy.at("absorbed").at(1).get<double>(), emitted, 5e-3 * emitted) << name;
        std::printf("[ figures  ] %s: emitted %.6g, absorbed %.6g (%.3g by backs), escaped 0\n", name,
                    emitted, energy.at("absorbed").at(1).get<double>(),
                    energy.at("behind").at(1).get<double>());
    }
}

// assets/hard/no_emitter.obj: nothing emits. Every method returns B = 0 at once, with residual 0 (the
// relative residual falls back to the absolute one instead of dividing by the zero emitted power).
TEST(NoEmitter, EveryMethodGivesZeroWithoutDividingByZero) {
    const Scene scene = load_scene(asset("no_emitter.obj"));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("no material emits light"), std::string::npos) << scene.warnings[0];
    const PatchMesh mesh = test::mesh(scene, 0.25);
    const UniformTransport system = make_uniform_transport(scene, mesh, compute_form_factors(mesh, {}));
    for (SolverMethod method : all_solver_methods()) {
        SCOPED_TRACE(std::string(solver_method_name(method)));
        auto solver = make_solver(method, system, SolverOptions{});
        const StepReport report = test::run_to_end(*solver, 10);
        EXPECT_TRUE(report.converged()) << solver->status_message();
        EXPECT_LE(report.step, 1u);
        EXPECT_EQ(report.residual, 0.0);
        for (const glm::dvec3& b : solver->solution()) ASSERT_EQ(b, glm::dvec3(0.0));
        for (const glm::dvec3& b : solver->display_solution()) ASSERT_EQ(b, glm::dvec3(0.0));
        const EnergyBalance balance = energy_balance(system, solver->solution());
        EXPECT_EQ(balance.emitted, glm::dvec3(0.0));
        EXPECT_EQ(balance.absorbed, glm::dvec3(0.0));
        EXPECT_EQ(balance.escaped, glm::dvec3(0.0));
    }
}

TEST(NoEmitter, TheCommandWarnsAndWritesZeros) {
    test::CommandResult result;
    const nlohmann::json doc = solve_json({asset("no_emitter.obj"), "--patch-size", "0.25"}, &result);
    EXPECT_NE(result.err.find("warning: "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("no material emits light"), std::string::npos) << result.err;
    const auto& stats = doc.at("stats");
    EXPECT_TRUE(stats.at("converged").get<bool>());
    EXPECT_EQ(stats.at("residual").get<double>(), 0.0);
    for (const auto& p : doc.at("patches")) {
        for (int c = 0; c < 3; ++c) ASSERT_EQ(p.at("radiosity").at(c).get<double>(), 0.0);
    }
}

// assets/hard/bright_dark.obj: Le = 1e6 (E = 3.1e6) beside walls of reflectance 1e-6. Every method gives
// finite, non-negative radiosity; the dark walls hold ρ H, about 1e-6 of what reaches them (not flushed
// to zero), and the solution scales linearly with the emission.
TEST(BrightAndDark, NoOverflowNoUnderflowAndLinearInTheEmission) {
    const Scene scene = load_scene(asset("bright_dark.obj"));
    const PatchMesh mesh = test::mesh(scene, 0.25);
    const UniformTransport bright = make_uniform_transport(scene, mesh, compute_form_factors(mesh, {}));
    UniformTransport unit = bright;
    for (glm::dvec3& e : unit.emission) e /= 1e6;
    for (SolverMethod method : all_solver_methods()) {
        SCOPED_TRACE(std::string(solver_method_name(method)));
        auto a = make_solver(method, bright, SolverOptions{});
        auto b = make_solver(method, unit, SolverOptions{});
        ASSERT_TRUE(test::run_to_end(*a).converged()) << a->status_message();
        ASSERT_TRUE(test::run_to_end(*b).converged()) << b->status_message();
        ASSERT_TRUE(test::all_finite(a->solution()));
        double dark_walls = 0.0;
        for (std::size_t i = 0; i < bright.size(); ++i) {
            const glm::dvec3 x = a->solution()[i];
            ASSERT_GE(std::min({x.x, x.y, x.z}), 0.0) << "patch " << i;
            EXPECT_NEAR(x.x, 1e6 * b->solution()[i].x, 1e-9 * x.x) << "patch " << i;
            if (bright.reflectance[i].x == 1e-6) {
                // B = E + ρ H on a dark wall with E = 0: B / ρ is the light arriving there, at least
                // 1000 (the floor alone, at B ≥ 8000, fills much of its view).
                EXPECT_GT(x.x / 1e-6, 1e3) << "patch " << i;
                dark_walls += 1.0;
            }
        }
        EXPECT_GT(dark_walls, 0.0);
    }
}

// Beyond the asset: emission from 1e-290 to 1e290 times the asset's, and reflectance 1e-300 or 0 on the
// dark walls. No method ever holds NaN or infinity. Up to 1e±100 every method converges; beyond that cg,
// whose inner products square the radiosity, stops (diverged above about 1e150, not converging below about
// 1e-150) with the last finite solution, while the other methods still converge.
TEST(BrightAndDark, ExtremeValuesNeverBecomeNaN) {
    const Scene scene = load_scene(asset("bright_dark.obj"));
    const PatchMesh mesh = test::mesh(scene, 0.5);
    const UniformTransport base = make_uniform_transport(scene, mesh, compute_form_factors(mesh, {}));
    for (double scale : {1e100, 1e-100, 1e290, 1e-290}) {
        for (double dark : {1e-300, 0.0}) {
            UniformTransport system = base;
            for (glm::dvec3& e : system.emission) e *= scale;
            for (glm::dvec3& r : system.reflectance) {
                if (r.x < 1e-3) r = glm::dvec3(dark);
            }
            for (SolverMethod method : all_solver_methods()) {
                SCOPED_TRACE(std::string(solver_method_name(method)) + " scale " +
                             std::to_string(std::log10(scale)) + " dark " + std::to_string(dark));
                auto solver = make_solver(method, system, SolverOptions{});
                const StepReport report = test::run_to_end(*solver);
                EXPECT_TRUE(test::all_finite(solver->solution()));
                EXPECT_FALSE(std::isnan(report.residual));
                const bool squares_overflow = std::abs(std::log10(scale)) > 150.0;
                if (method != SolverMethod::conjugate_gradient || !squares_overflow) {
                    EXPECT_TRUE(report.converged()) << solver->status_message();
                    for (const glm::dvec3& b : solver->solution()) ASSERT_GE(b.x, 0.0);
                }
            }
        }
    }
}

// Float storage: the form factors are stored in float (accumulated in double). Solving with the stored
// matrix and with the same factors kept in double (the estimator's own rows) gives the same radiosity to
// 1e-4, in an ordinary room and in a closed one at ρ = 0.999, where errors are amplified a thousandfold.
std::vector<std::vector<double>> double_rows(const PatchMesh& mesh) {
    const RayScene scene(mesh);
    const RowFunction row = analytic_rows(mesh, scene, kDefaultAnalyticRays, 1);
    std::vector<std::vector<double>> f(mesh.size(), std::vector<double>(mesh.size(), 0.0));
    std::vector<RowEntry> entries;
    RowStats stats;
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
        entries.clear();
        row(i, entries, stats);
        for (const RowEntry& e : entries) f[i][e.column] = e.value;
    }
    return f;
}

// (I − ρF) B = E for one channel by Gaussian elimination with partial pivoting, all in double.
std::vector<double> solve_in_double(std::vector<std::vector<double>> f, const UniformTransport& system,
                                    int c) {
    const std::size_t n = f.size();
    std::vector<double> b(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j)
            f[i][j] = (i == j ? 1.0 : 0.0) - system.reflectance[i][c] * f[i][j];
        b[i] = system.emission[i][c];
    }
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t pivot = k;
        for (std::size_t i = k + 1; i < n; ++i) {
            if (std::abs(f[i][k]) > std::abs(f[pivot][k])) pivot = i;
        }
        std::swap(f[k], f[pivot]);
        std::swap(b[k], b[pivot]);
        for (std::size_t i = k + 1; i < n; ++i) {
            const double m = f[i][k] / f[k][k];
            if (m == 0.0) continue;
            for (std::size_t j = k; j < n; ++j) f[i][j] -= m * f[k][j];
            b[i] -= m * b[k];
        }
    }
    for (std::size_t k = n; k-- > 0;) {
        for (std::size_t j = k + 1; j < n; ++j) b[k] -= f[k][j] * b[j];
        b[k] /= f[k][k];
    }
    return b;
}

void expect_float_storage_agrees(const std::string& name, double patch_size) {
    const Scene scene = load_scene(asset(name));
    const PatchMesh mesh = test::mesh(scene, patch_size);
    FormFactorOptions options;
    options.method = FormFactorMethod::analytic;
    const UniformTransport system = make_uniform_transport(scene, mesh, compute_form_factors(mesh, options));
    std::vector<std::vector<double>> f = double_rows(mesh);
    // The stored matrix is the double one rounded to float; rows of partly covered patches are then those of
    // their exposed part (divided by the exposed share after rounding, so within a float step or two).
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const double exposed = system.form_factors.exposed_fraction(i);
        for (double& value : f[i]) value /= exposed;
        const FormFactorRow row = system.form_factors.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            const float expected = static_cast<float>(f[i][row.columns[k]]);
            if (exposed == 1.0) {
                ASSERT_EQ(row.values[k], expected);
            } else {
                ASSERT_NEAR(row.values[k], expected, 4e-7 * expected);
            }
        }
    }
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    ASSERT_TRUE(solver->step().converged());
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const std::vector<double> reference = solve_in_double(f, system, c);
        for (std::size_t i = 0; i < mesh.size(); ++i) {
            worst = std::max(worst, std::abs(solver->solution()[i][c] - reference[i]) / reference[i]);
        }
    }
    std::printf("[ figures  ] %s: float storage against double, largest relative difference %.2e\n",
                name.c_str(), worst);
    EXPECT_LT(worst, 1e-4);
}

TEST(FloatStorage, AgreesWithDoubleInAnOrdinaryRoom) {
    expect_float_storage_agrees("scale_room.obj", 0.25);
}

TEST(FloatStorage, AgreesWithDoubleAtHighAlbedo) {
    expect_float_storage_agrees("furnace_rho_0_999.obj", 0.25);
}

}  // namespace
}  // namespace rad
