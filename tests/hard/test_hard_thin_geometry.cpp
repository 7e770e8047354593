// Hard cases: thin and lopsided geometry. Plates nearly touching (their form factor must approach 1 and never
// pass it), sliver triangles of aspect 1e4 and a patch a millionth the area of its neighbour: no NaN, no
// negative radiosity, and an error bounded by the estimator's usual one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "form_factor_test_scenes.hpp"
#include "geometry/quadrature.hpp"
#include "rad/geometry/point_polygon_factor.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "solved_scene.hpp"
#include "solver_test_systems.hpp"

namespace rad {
namespace {

std::string asset(const std::string& name) {
    return std::string(RAD_SOURCE_DIR) + "/assets/hard/" + name;
}

std::string method_name(FormFactorMethod method) {
    return method == FormFactorMethod::analytic ? "analytic" : "hemisphere";
}

FormFactorMatrix form_factors(const PatchMesh& patches, FormFactorMethod method) {
    FormFactorOptions options;
    options.method = method;
    return compute_form_factors(patches, options);
}

double largest_row_sum(const FormFactorMatrix& f) {
    double largest = 0.0;
    for (std::size_t i = 0; i < f.rows(); ++i) {
        const double sum = f.row(i).sum();
        largest = std::max(largest, sum);
    }
    return largest;
}

class NearPlates : public ::testing::TestWithParam<FormFactorMethod> {};

// assets/hard/near_plates.obj: unit squares 1e-4 apart. F = 0.99980007 (closed form); both estimators get it
// to within 2e-4 (the analytic quadrature stops refining at patch / 64, coarser than the gap, and slightly
// overestimates; 4096 hemisphere rays from a whole plate expect 0.8 of them to escape), and never above 1.
TEST_P(NearPlates, AtATenThousandthOfTheirSizeFIsNearlyOneAndNotMore) {
    const Scene scene = load_scene(asset("near_plates.obj"));
    const double exact = test::parallel_rectangles_factor(1, 1, 1e-4);
    for (double patch_size : {1.0, 0.25}) {
        const PatchMesh mesh = test::mesh(scene, patch_size);
        const FormFactorMatrix f = form_factors(mesh, GetParam());
        const double factor = test::surface_factor(f, mesh, 0, 1);
        std::printf("[ figures  ] %s, patch size %g: F = %.8f (closed form %.8f)\n",
                    method_name(GetParam()).c_str(), patch_size, factor, exact);
        EXPECT_NEAR(factor, exact, 2e-4) << "patch size " << patch_size;
        EXPECT_LE(factor, 1.0);
        EXPECT_LE(largest_row_sum(f), 1.0 + 1e-6);  // float rounding of the row's entries

        // The lower plate emits E = 1 and both reflect 0.5: B_lower = E / (1 − (ρF)²) → 4/3 as F → 1.
        const UniformTransport system = make_uniform_transport(scene, mesh, f);
        auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
        ASSERT_TRUE(solver->step().converged());
        for (const glm::dvec3& b : solver->solution()) {
            EXPECT_TRUE(std::isfinite(b.x) && b.x >= 0.0 && b.x <= 4.0 / 3.0 + 1e-9) << b.x;
        }
    }
}

// As the gap closes, F rises towards 1 and stays at or below it, down to a gap of 1e-5 of the plates' size.
// Rays leave a patch 3.8e-6 of the size off its surface (the smallest offset that keeps float rounding from
// making a ray hit the patch it leaves): plates nearer than that do not see each other.
TEST_P(NearPlates, FRisesTowardsOneAsTheGapCloses) {
    double previous = 0.0;
    for (double gap : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
        const Scene scene = test::parallel_rectangles(1, 1, gap);
        const PatchMesh mesh = test::mesh(scene, 0.25);
        const FormFactorMatrix f = form_factors(mesh, GetParam());
        const double factor = test::surface_factor(f, mesh, 0, 1);
        const double exact = test::parallel_rectangles_factor(1, 1, gap);
        std::printf("[ figures  ] %s, gap %g: F = %.8f (closed form %.8f)\n", method_name(GetParam()).c_str(),
                    gap, factor, exact);
        // Hemisphere: 16 x 4096 rays from the lower plate leave F a standard deviation of sqrt(F (1 − F) /
        // 65536).
        EXPECT_NEAR(factor, exact, 2e-4 + 0.05 * (1.0 - exact)) << "gap " << gap;
        EXPECT_LE(factor, 1.0) << "gap " << gap;
        EXPECT_LE(largest_row_sum(f), 1.0 + 1e-6) << "gap " << gap;
        EXPECT_GT(factor, previous - 1e-4) << "gap " << gap;
        previous = factor;
    }
}

INSTANTIATE_TEST_SUITE_P(Estimators, NearPlates,
                         ::testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) { return method_name(info.param); });

// The light of the sliver and tiny-patch scenes: y = 1, facing down, counter-clockwise seen from below.
const std::vector<glm::dvec3> kUnitLight = {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};

// ρ (1/A) ∫ F(x -> light) dA over a patch facing up, by Radon's 7-point rule on its triangles: the factor
// varies slowly across a patch this far from the light.
double direct_radiosity(const PatchMesh& mesh, std::size_t patch, double reflectance) {
    const glm::uvec4& c = mesh.corners[patch];
    const glm::dvec3 up(0, 1, 0);
    double integral = 0.0;
    auto triangle = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d) {
        double sum = 0.0;
        for (const TriangleNode& n : kRadon7) {
            sum += n.weight * point_polygon_factor(n.a * a + n.b * b + (1 - n.a - n.b) * d, up, kUnitLight);
        }
        integral += Triangle{a, b, d}.area() * sum;
    };
    triangle(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]]);
    if (!mesh.is_triangle(patch)) triangle(mesh.points[c[0]], mesh.points[c[2]], mesh.points[c[3]]);
    return reflectance * integral / mesh.patches[patch].area;
}

struct Solved {
    bool analytic = false;
    Scene scene;
    PatchMesh mesh;
    UniformTransport system;
    // The solution of every solver, in all_solver_methods() order.
    std::vector<std::vector<glm::dvec3>> by_method;
};

Solved solve_every_way(const std::string& name, double patch_size, FormFactorMethod method) {
    Solved s;
    s.analytic = method == FormFactorMethod::analytic;
    s.scene = load_scene(asset(name));
    s.mesh = test::mesh(s.scene, patch_size);
    s.system = make_uniform_transport(s.scene, s.mesh, form_factors(s.mesh, method));
    for (SolverMethod m : all_solver_methods()) {
        auto solver = make_solver(m, s.system, SolverOptions{});
        const StepReport report = test::run_to_end(*solver);
        EXPECT_TRUE(report.converged()) << solver_method_name(m) << ": " << solver->status_message();
        s.by_method.emplace_back(solver->solution().begin(), solver->solution().end());
    }
    return s;
}

class Lopsided : public ::testing::TestWithParam<FormFactorMethod> {};

// assets/hard/sliver.obj: two triangles 1 long and 1e-4 wide, cut into 16 slivers each, under a unit light.
// Every method gives every sliver patch its direct light, ρ F(patch -> light), to within 8 % (hemisphere,
// 4096 rays at F ≈ 0.2) or 0.01 % (analytic).
TEST_P(Lopsided, SliverTrianglesGetTheirDirectLight) {
    const Solved s = solve_every_way("sliver.obj", 0.25, GetParam());
    ASSERT_EQ(s.scene.surfaces[1].name, "sliver");
    const double tolerance = GetParam() == FormFactorMethod::analytic ? 1e-4 : 0.08;
    double worst = 0.0;
    for (std::size_t m = 0; m < s.by_method.size(); ++m) {
        const auto& b = s.by_method[m];
        ASSERT_TRUE(test::all_finite(b));
        for (std::uint32_t i = s.mesh.surface_begin[1]; i < s.mesh.surface_begin[2]; ++i) {
            double longest = 0.0;
            for (int k = 0; k < 3; ++k) {
                longest = std::max(longest, glm::length(s.mesh.points[s.mesh.corners[i][(k + 1) % 3]] -
                                                        s.mesh.points[s.mesh.corners[i][k]]));
            }
            ASSERT_GT(longest * longest / s.mesh.patches[i].area, 1e4) << "patch " << i << " is not a sliver";
            const double expected = direct_radiosity(s.mesh, i, 0.5);
            for (int c = 0; c < 3; ++c) EXPECT_GE(b[i][c], 0.0);
            worst = std::max(worst, std::abs(b[i].x / expected - 1.0));
            EXPECT_NEAR(b[i].x, expected, tolerance * expected)
                << solver_method_name(all_solver_methods()[m]) << ", patch " << i;
        }
    }
    std::printf("[ figures  ] %s: slivers' largest relative error %.2e\n", method_name(GetParam()).c_str(),
                worst);
}

void expect_direct_light_on_tiny_and_huge(const Solved& s) {
    ASSERT_EQ(s.mesh.size(), 3u);
    EXPECT_NEAR(s.mesh.patches[1].area / s.mesh.patches[2].area, 1e6, 1e-3);
    const double floor_expected = 0.5 * test::parallel_rectangles_factor(1, 1, 1);
    const double tiny_expected = direct_radiosity(s.mesh, 2, 0.5);
    const double tolerance = s.analytic ? 1e-4 : 0.03;
    for (std::size_t m = 0; m < s.by_method.size(); ++m) {
        SCOPED_TRACE(std::string(solver_method_name(all_solver_methods()[m])));
        const auto& b = s.by_method[m];
        ASSERT_TRUE(test::all_finite(b));
        EXPECT_NEAR(b[1].x, floor_expected, tolerance * floor_expected);
        EXPECT_NEAR(b[2].x, tiny_expected, tolerance * tiny_expected);
        for (const glm::dvec3& x : b) EXPECT_GE(std::min({x.x, x.y, x.z}), 0.0);
    }
}

// assets/hard/tiny_beside_huge.obj at one patch per surface: the floor (area 1) and, beside it, a square of
// area 1e-6. The light's rays all but never find the tiny square (F_light,tiny ≈ 2e-7), while the tiny
// square's own rays find the light: every method gives both patches their direct light, cg included (it
// weighs a pair's two estimates by their inverse variances, which keeps the tiny patch's own estimate; the
// plain mean it took before halved the tiny patch's light). --reciprocity still takes the plain mean, and
// with it the tiny patch gets half its light.
TEST_P(Lopsided, ATinyPatchBesideAHugeOneGetsItsDirectLight) {
    expect_direct_light_on_tiny_and_huge(solve_every_way("tiny_beside_huge.obj", 2.0, GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Estimators, Lopsided,
                         ::testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) { return method_name(info.param); });

// A furnace of UV spheres whose poles are fans of thin triangles (64 segments: 5.6° wide at the pole, 70
// times as long as wide there), every face ρ = 0.5 and E = 1, so B = E / (1 − ρ) = 2 on every element under
// clustering (what scenes of many faces get).
TEST(Slivers, AFurnaceOfUvSpheresIsRightOnEveryElement) {
    SphereRoom room;
    room.segments = 64;
    room.triangles = true;
    room.shared_corners = true;
    room.spheres = 2;
    room.balls = 2;
    room.source = "uv-sphere furnace";
    const auto s = test::solve_scene(make_sphere_room(room), Subdivision::clustered);
    double worst = 0.0;
    for (const glm::dvec3& b : s->radiosity) worst = std::max(worst, std::abs(b.x - 2.0) / 2.0);
    EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace rad
