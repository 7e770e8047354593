// Hard case: surfaces that meet. Along a shared edge the form-factor kernel cos θ cos θ' / π r² is singular,
// and where a box stands on a floor, rays that start on the floor next to the seam, or under the box, could
// slip through it. The factors near an edge must stay finite and match the closed forms; no light may leak
// under a box or through the seam beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {
namespace {

std::string asset(const std::string& name) {
    return std::string(RAD_SOURCE_DIR) + "/assets/hard/" + name;
}

FormFactorMatrix form_factors(const PatchMesh& patches, FormFactorMethod method) {
    FormFactorOptions options;
    options.method = method;
    if (method == FormFactorMethod::hemisphere) options.rays = 4096;  // the tolerances below are for 4096
    return compute_form_factors(patches, options);
}

std::string method_name(FormFactorMethod method) {
    return method == FormFactorMethod::analytic ? "analytic" : "hemisphere";
}

// assets/hard/perpendicular_squares.obj: the floor and the wall, unit squares sharing the edge x = y = 0
// along z, cut into n x n patches of side s. A floor patch and a wall patch over the same stretch of the
// edge share an edge of length s: F = F⊥(s, s, s) = 0.200044. Patches over neighbouring stretches touch at
// one point of the edge: by the reciprocity algebra of two such pairs and the 2s-long pair they make,
// F = F⊥(s, s, 2s) − F⊥(s, s, s).
class PerpendicularSquares : public ::testing::TestWithParam<FormFactorMethod> {};

TEST_P(PerpendicularSquares, FactorsAlongTheSharedEdgeAreFiniteAndMatchTheClosedForms) {
    const FormFactorMethod method = GetParam();
    const Scene scene = load_scene(asset("perpendicular_squares.obj"));
    const double s = 0.125;
    const PatchMesh mesh = test::mesh(scene, s);
    ASSERT_EQ(mesh.size(), 128u);
    const FormFactorMatrix f = form_factors(mesh, method);

    const double sharing_an_edge = test::perpendicular_rectangles_factor(s, s, s);
    const double sharing_a_point = test::perpendicular_rectangles_factor(s, s, 2 * s) - sharing_an_edge;
    // Analytic: the kernel is integrated adaptively down to the edge, so only float storage is left.
    // Hemisphere: 4096 rays give F ≈ 0.2 with a standard deviation of about 3 %.
    const double edge_tolerance = method == FormFactorMethod::analytic ? 1e-6 : 0.12;
    const double point_tolerance = method == FormFactorMethod::analytic ? 1e-6 : 0.3;
    int edge_pairs = 0, point_pairs = 0;
    double worst_edge = 0.0, worst_point = 0.0;
    for (std::size_t i = 0; i < f.rows(); ++i) {
        double row_sum = 0.0;
        const FormFactorRow row = f.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            const float value = row.values[k];
            ASSERT_TRUE(std::isfinite(value) && value > 0.0f)
                << "F_" << i << "," << row.columns[k] << " = " << value;
            row_sum += value;
            const Patch& a = mesh.patches[i];
            const Patch& b = mesh.patches[row.columns[k]];
            // Both patches in the first row along the edge: centroid s/2 from it.
            const bool at_edge = a.centroid.x + a.centroid.y < s && b.centroid.x + b.centroid.y < s;
            if (!at_edge || a.surface == b.surface) continue;
            const double dz = std::abs(a.centroid.z - b.centroid.z);
            if (dz < 1e-9) {
                worst_edge = std::max(worst_edge, std::abs(value / sharing_an_edge - 1.0));
                ++edge_pairs;
            } else if (std::abs(dz - s) < 1e-9) {
                worst_point = std::max(worst_point, std::abs(value / sharing_a_point - 1.0));
                ++point_pairs;
            }
        }
        EXPECT_LE(row_sum, 1.0 + 1e-6) << "row " << i;
    }
    std::printf("[ figures  ] %s: largest error of F for patches sharing an edge %.2e, a point %.2e\n",
                method_name(method).c_str(), worst_edge, worst_point);
    EXPECT_EQ(edge_pairs, 16);   // 8 stretches, both ways
    EXPECT_EQ(point_pairs, 28);  // 7 pairs of neighbouring stretches, two pairs each, both ways
    EXPECT_LT(worst_edge, edge_tolerance) << method_name(method);
    EXPECT_LT(worst_point, point_tolerance) << method_name(method);
    // The whole floor to the whole wall: 0.200044.
    const double whole = test::surface_factor(f, mesh, 0, 1);
    EXPECT_NEAR(whole, test::perpendicular_rectangles_factor(1, 1, 1),
                (method == FormFactorMethod::analytic ? 1e-5 : 2e-3) * whole);
}

INSTANTIATE_TEST_SUITE_P(Estimators, PerpendicularSquares,
                         ::testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) { return method_name(info.param); });

// assets/hard/box_on_floor.obj at patch size 0.25, whose grid lines fall on the box's and the panel's edges.
// Only the floor reflects, and it cannot see itself, so every floor patch holds exactly the direct light of
// the panel that reaches it: nothing where no line to the panel is free.
class BoxOnFloor : public ::testing::TestWithParam<FormFactorMethod> {};

TEST_P(BoxOnFloor, NoLightUnderTheBoxOrThroughItsSeams) {
    const Scene scene = load_scene(asset("box_on_floor.obj"));
    // The box's bottom face lies on the floor facing the other way: not an overlap to resolve.
    for (const std::string& w : scene.warnings)
        EXPECT_EQ(w.find("lies in the plane"), std::string::npos) << w;
    const PatchMesh mesh = test::mesh(scene, 0.25);
    ASSERT_EQ(scene.surfaces[0].name, "floor");
    const UniformTransport system = make_uniform_transport(scene, mesh, form_factors(mesh, GetParam()));
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    ASSERT_TRUE(solver->step().converged());
    const auto b = solver->solution();

    int under = 0, umbra = 0, behind = 0, lit = 0;
    for (std::uint32_t i = mesh.surface_begin[0]; i < mesh.surface_begin[1]; ++i) {
        const glm::dvec3 c = mesh.patches[i].centroid;
        const bool in_panel_strip = c.z > 1.75 && c.z < 2.25;
        SCOPED_TRACE("floor patch at x " + std::to_string(c.x) + ", z " + std::to_string(c.z));
        if (c.x > 1.5 && c.x < 2.5 && c.z > 1.5 && c.z < 2.5) {
            ++under;
        } else if (in_panel_strip && c.x > 2.5) {
            EXPECT_EQ(b[i], glm::dvec3(0.0)) << "in the box's umbra";
            ++umbra;
        } else if (in_panel_strip && c.x < 0.5) {
            EXPECT_EQ(b[i], glm::dvec3(0.0)) << "behind the panel";
            ++behind;
        } else if (in_panel_strip && c.x < 1.5) {
            EXPECT_GT(b[i].x, 0.0) << "in front of the panel";
            ++lit;
        }
        EXPECT_GE(b[i].x, 0.0);
    }
    EXPECT_EQ(under, 0);  // the floor under the closed box is cut away (cut_faces_at_solids)
    EXPECT_EQ(umbra, 12);
    EXPECT_EQ(behind, 4);
    EXPECT_EQ(lit, 8);
}

INSTANTIATE_TEST_SUITE_P(Estimators, BoxOnFloor,
                         ::testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) { return method_name(info.param); });

// Seams between patches: a closed room lets no ray out, so every hemisphere row of assets/hard/no_emitter.obj
// must sum to 1. At 16 x 16 patches a face, one ray of 6.3 million meets the ceiling exactly on the edge
// shared by two of its patches and passes between them (Embree's default intersection test is not
// watertight): a leak of 1/4096 of that row. RTC_SCENE_FLAG_ROBUST on the scene (core/src/embree_scene.cpp)
// closes it.
TEST(Seams, NoRayPassesBetweenTwoPatchesOfAClosedRoom) {
    const Scene scene = load_scene(asset("no_emitter.obj"));
    const PatchMesh mesh = test::mesh(scene, 1.0 / 16.0);
    FormFactorReport report;
    const FormFactorMatrix f = compute_form_factors(mesh, FormFactorOptions{}, &report);
    EXPECT_EQ(report.escaped_ray_fraction, 0.0);
    for (std::size_t i = 0; i < f.rows(); ++i) {
        const double sum = f.row(i).sum();
        EXPECT_NEAR(sum, 1.0, 1e-6) << "row " << i << ", centroid " << mesh.patches[i].centroid.x << " "
                                    << mesh.patches[i].centroid.y << " " << mesh.patches[i].centroid.z;
    }
}

}  // namespace
}  // namespace rad
