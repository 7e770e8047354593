// Hard case: big polygons, as CAD exporters write them (assets/hard/big_polygons.obj). A convex disk of 256
// corners is one face, whole (tinyobjloader keeps a face's corner count in a byte, so it used to read as 0
// and the disk was dropped); a concave star of 24 corners is triangulated without gaps or overlaps. Both are
// lit by the light above them, and the energy balances.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

const Surface& surface(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces)
        if (s.name == name) return s;
    ADD_FAILURE() << "no surface " << name;
    return scene.surfaces.front();
}

// The star's outline as the asset writes it: 24 corners alternating between radii 0.3 and 0.12.
double star_area() {
    double twice = 0.0;
    for (int k = 0; k < 24; ++k) {
        auto corner = [](int i) {
            const double a = 2.0 * std::numbers::pi * (i % 24) / 24.0, r = i % 2 == 0 ? 0.3 : 0.12;
            return std::array<double, 2>{r * std::cos(a), -r * std::sin(a)};
        };
        const auto p = corner(k), q = corner(k + 1);
        twice += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * std::abs(twice);
}

TEST(BigPolygons, TheDiskIsOneWholeFaceAndTheStarKeepsItsArea) {
    const Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/big_polygons.obj");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    const Surface& disk = surface(scene, "disk");
    EXPECT_EQ(disk.mesh.n_faces(), 1u);
    EXPECT_EQ(disk.mesh.n_vertices(), 256u);
    EXPECT_NEAR(surface_area(disk.mesh), 128.0 * 0.16 * std::sin(2.0 * std::numbers::pi / 256.0), 1e-12);
    const Surface& star = surface(scene, "star");
    EXPECT_EQ(star.mesh.n_faces(), 22u);  // n − 2 triangles
    EXPECT_NEAR(surface_area(star.mesh), star_area(), 1e-12);
}

TEST(BigPolygons, BothAreLitAndTheEnergyBalances) {
    const Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/big_polygons.obj");
    const PatchMesh patches = build_patches(scene, MeshingOptions{.patch_size = 0.2});
    const UniformTransport system = make_uniform_transport(scene, patches, compute_form_factors(patches, {}));
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    while (!solver->report().finished()) solver->step();
    const EnergyBalance balance = energy_balance(system, solver->solution());
    EXPECT_NEAR(balance.emitted.y, 0.56, 1e-12);  // the light: area 0.56, E = 1
    EXPECT_NEAR(balance.absorbed.y + balance.escaped.y, balance.emitted.y, 5e-3 * balance.emitted.y);
    // Every patch of the disk and the star sees the light: each gets direct light.
    for (std::size_t i = 0; i < system.size(); ++i) {
        if (system.emission[i].y > 0.0) continue;
        EXPECT_GT(solver->solution()[i].y, 0.0) << "patch " << i;
    }
}

}  // namespace
}  // namespace rad
