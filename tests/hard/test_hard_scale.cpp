// Hard case: scale. Radiosity is power per area, so the same scene at 1e-3 and at 1e4 times its size must
// have the same radiosity, patch for patch. Nothing in the program has a length built in: the default patch
// size, the rays' offset from their patch and every tolerance are shares of the scene's size. What is left is
// float rounding: Embree traces rays in float, and 1e-3 and 1e4 round differently (powers of two do not).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {
namespace {

// assets/hard/scale_room.obj scaled by `scale`, meshed at an eighth of its size (the default, a sixteenth,
// makes four times the patches for the same finding), solved directly.
std::vector<glm::dvec3> solve_scaled(double scale, FormFactorMethod method, std::size_t* patches = nullptr) {
    Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/scale_room.obj");
    for (Surface& s : scene.surfaces) {
        for (auto v : s.mesh.vertices()) s.mesh.set_point(v, s.mesh.point(v) * scale);
    }
    EXPECT_DOUBLE_EQ(default_patch_size(scene), scale / 16.0);
    const PatchMesh mesh = build_patches(scene, MeshingOptions{.patch_size = scale / 8.0});
    if (patches) *patches = mesh.size();
    FormFactorOptions options;
    options.method = method;
    const UniformTransport system = make_uniform_transport(scene, mesh, compute_form_factors(mesh, options));
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    EXPECT_TRUE(solver->step().converged());
    return {solver->solution().begin(), solver->solution().end()};
}

double largest_relative_difference(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    EXPECT_EQ(a.size(), b.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[i][c] - b[i][c]) / b[i][c]);
    }
    return worst;
}

// Analytic factors: the kernel and its quadrature are in double, and shadow rays between the interiors of
// two patches meet the same surfaces at any scale. Within 1e-5 (measured: 3e-6).
TEST(Scale, AnalyticRadiosityIsTheSameAtAThousandthAndTenThousandTimesTheSize) {
    std::size_t patches = 0;
    const std::vector<glm::dvec3> unit = solve_scaled(1.0, FormFactorMethod::analytic, &patches);
    EXPECT_GT(patches, 400u);
    for (double scale : {1e-3, 1e4}) {
        const double difference =
            largest_relative_difference(solve_scaled(scale, FormFactorMethod::analytic), unit);
        std::printf("[ figures  ] analytic, scale %g: largest relative difference %.2e\n", scale, difference);
        EXPECT_LT(difference, 1e-5) << "scale " << scale;
    }
}

// Hemisphere factors (the default): the same rays. Embree sees geometry and rays in the scene's normalized
// frame, rounded to float only there, so at any scale the float rays and patches are the same and so is the
// answer (before the normalization, at 1e-3 and 1e4 a ray grazing an edge could land on its other side:
// 2.8e-4 on one patch).
TEST(Scale, HemisphereRadiosityIsTheSameAtAThousandthAndTenThousandTimesTheSize) {
    const std::vector<glm::dvec3> unit = solve_scaled(1.0, FormFactorMethod::hemisphere);
    for (double scale : {0x1p-10, 0x1p13}) {
        EXPECT_EQ(largest_relative_difference(solve_scaled(scale, FormFactorMethod::hemisphere), unit), 0.0)
            << "scale " << scale;
    }
    for (double scale : {1e-3, 1e4}) {
        const std::vector<glm::dvec3> scaled = solve_scaled(scale, FormFactorMethod::hemisphere);
        const double difference = largest_relative_difference(scaled, unit);
        double moved = 0.0, total = 0.0;
        for (std::size_t i = 0; i < unit.size(); ++i) {
            moved += std::abs(scaled[i].x - unit[i].x);
            total += unit[i].x;
        }
        std::printf("[ figures  ] hemisphere, scale %g: largest relative difference %.2e, overall %.2e\n",
                    scale, difference, moved / total);
        EXPECT_LT(difference, 1e-5) << "scale " << scale;
        EXPECT_LT(moved / total, 1e-7) << "scale " << scale;
    }
}

}  // namespace
}  // namespace rad
