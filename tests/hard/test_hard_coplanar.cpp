// Hard case: coplanar overlapping surfaces. The published Cornell box's light lies in the ceiling's plane and
// the ceiling quad covers it; a rug may lie in a floor's. Two surfaces in one place tie: rays and the depth
// buffer pick either, so the light is hidden or blotched, a rug speckles, and the light arriving there is
// split between the two. The loader detects two surfaces lying in one plane, facing the same way and
// overlapping, warns, and moves the emitter (else the smaller surface) a thousandth of the scene's diagonal
// in front of the other: the light is what is seen and hit, the ceiling behind it receives (almost) nothing,
// and the room is lit as if the opening were cut out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {
namespace {

std::string asset(const std::string& name) {
    return std::string(RAD_SOURCE_DIR) + "/" + name;
}

const Surface& surface(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces) {
        if (s.name == name) return s;
    }
    throw std::runtime_error("no surface " + name);
}

std::uint32_t surface_index(const Scene& scene, const std::string& name) {
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        if (scene.surfaces[s].name == name) return s;
    }
    throw std::runtime_error("no surface " + name);
}

// Every corner's height (y) on a surface, the least and the greatest.
std::pair<double, double> heights(const Surface& s) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (auto v : s.mesh.vertices()) {
        lo = std::min(lo, s.mesh.point(v)[1]);
        hi = std::max(hi, s.mesh.point(v)[1]);
    }
    return {lo, hi};
}

int lift_warnings(const Scene& scene) {
    int count = 0;
    for (const std::string& w : scene.warnings) count += w.find("lies in the plane of") != std::string::npos;
    return count;
}

TEST(Coplanar, TheCoveringLightIsMovedInFrontOfTheCeilingWithAWarning) {
    const Scene scene = load_scene(asset("assets/hard/coplanar_light.obj"));
    ASSERT_EQ(lift_warnings(scene), 1);
    for (const std::string& w : scene.warnings) {
        if (w.find("lies in the plane") == std::string::npos) continue;
        EXPECT_NE(w.find("coplanar_light.obj: the emitter 'light' lies in the plane of 'ceiling'"),
                  std::string::npos)
            << w;
        EXPECT_NE(w.find("0.001 of the scene's size"), std::string::npos) << w;
    }
    const double lift = 1e-3 * std::sqrt(3.0);  // the unit room's diagonal
    const auto [light_lo, light_hi] = heights(surface(scene, "light"));
    EXPECT_NEAR(light_lo, 1.0 - lift, 1e-12);
    EXPECT_NEAR(light_hi, 1.0 - lift, 1e-12);
    EXPECT_EQ(heights(surface(scene, "ceiling")), std::make_pair(1.0, 1.0));
}

TEST(Coplanar, ThePublishedCornellBoxLightIsMovedAMillimetreDown) {
    const Scene scene = load_scene(asset("assets/cornell_box.obj"));
    ASSERT_EQ(lift_warnings(scene), 1);
    const double diagonal = std::sqrt(556.0 * 556.0 + 548.8 * 548.8 + 559.2 * 559.2);
    const auto [lo, hi] = heights(surface(scene, "light"));
    EXPECT_NEAR(lo, 548.8 - 1e-3 * diagonal, 1e-9);
    EXPECT_NEAR(hi, 548.8 - 1e-3 * diagonal, 1e-9);
    EXPECT_NEAR(surface_area(surface(scene, "light").mesh), 130.0 * 105.0, 1e-9);
}

// Surfaces that only touch, or lie in one plane facing opposite ways, are left alone: builtin:cornell's
// light in its opening (edges shared with the ceiling's pieces), the reference room, a box standing on a
// floor with its bottom face down.
TEST(Coplanar, TouchingOrOppositeSurfacesAreLeftAlone) {
    EXPECT_EQ(lift_warnings(make_cornell_box()), 0);
    EXPECT_EQ(lift_warnings(load_scene(asset("assets/hard/coplanar_light_reference.obj"))), 0);
    EXPECT_EQ(lift_warnings(load_scene(asset("assets/hard/box_on_floor.obj"))), 0);
    EXPECT_EQ(lift_warnings(load_scene(asset("assets/hard/scale_room.obj"))), 0);
}

// A lamp lying across two coplanar floor tiles is moved once, up (the tiles' front), with a warning for each.
TEST(Coplanar, ALightAcrossTwoSurfacesIsMovedOnce) {
    PolygonSoup soup;
    soup.source = "two";
    soup.positions = {{0, 0, 0}, {0, 0, 1},      {1, 0, 1},      {1, 0, 0},      {2, 0, 1},
                      {2, 0, 0}, {0.5, 0, 0.25}, {0.5, 0, 0.75}, {1.5, 0, 0.75}, {1.5, 0, 0.25}};
    soup.groups = {{"left", Material{"grey", glm::dvec3(0.5), glm::dvec3(0.0)}},
                   {"right", Material{"grey", glm::dvec3(0.5), glm::dvec3(0.0)}},
                   {"lamp", Material{"lamp", glm::dvec3(0.5), glm::dvec3(1.0)}}};
    soup.polygons = {{{0, 1, 2, 3}, 0}, {{3, 2, 4, 5}, 1}, {{6, 7, 8, 9}, 2}};
    const Scene built = build_scene(soup);
    EXPECT_EQ(lift_warnings(built), 2);
    const auto [lo, hi] = heights(surface(built, "lamp"));
    EXPECT_NEAR(lo, 1e-3 * std::sqrt(5.0), 1e-12);  // up: the floor's front
    EXPECT_NEAR(hi, 1e-3 * std::sqrt(5.0), 1e-12);
}

// Two surfaces that do not emit, a rug in the floor's plane: the smaller, the rug, is moved up (the floor's
// front), with a warning naming both; the floor stays.
TEST(Coplanar, ARugInTheFloorsPlaneIsMovedInFrontOfIt) {
    PolygonSoup soup;
    soup.source = "room";
    soup.positions = {{0, 0, 0},     {0, 0, 2},     {2, 0, 2},     {2, 0, 0},
                      {0.5, 0, 0.5}, {0.5, 0, 1.5}, {1.5, 0, 1.5}, {1.5, 0, 0.5}};
    soup.groups = {{"floor", Material{"grey", glm::dvec3(0.5), glm::dvec3(0.0)}},
                   {"rug", Material{"red", glm::dvec3(0.7, 0.05, 0.05), glm::dvec3(0.0)}}};
    soup.polygons = {{{0, 1, 2, 3}, 0}, {{4, 5, 6, 7}, 1}};
    const Scene built = build_scene(soup);
    ASSERT_EQ(lift_warnings(built), 1);
    EXPECT_NE(built.warnings.front().find("room: 'rug' lies in the plane of 'floor'"), std::string::npos)
        << built.warnings.front();
    const double lift = 1e-3 * std::sqrt(8.0);  // the diagonal of the 2 x 0 x 2 box
    const auto [lo, hi] = heights(surface(built, "rug"));
    EXPECT_NEAR(lo, lift, 1e-12);
    EXPECT_NEAR(hi, lift, 1e-12);
    EXPECT_EQ(heights(surface(built, "floor")), std::make_pair(0.0, 0.0));
}

// A file of 2000 stacked faces, each its own surface (a bad export): every pair overlaps, 2 million pairs.
// The search stops after its bound with one warning, and the pairs of names are warned about once each.
TEST(Coplanar, AStackOfThousandsOfFacesIsBoundedInWorkAndWarnings) {
    PolygonSoup soup;
    soup.source = "stack";
    for (int i = 0; i < 2000; ++i) {
        const double d = 1e-7 * i;  // not exact duplicates, which are dropped before
        const auto first = static_cast<std::uint32_t>(soup.positions.size());
        soup.positions.insert(soup.positions.end(),
                              {{d, 0, d}, {d, 0, 1 + d}, {1 + d, 0, 1 + d}, {1 + d, 0, d}});
        soup.groups.push_back({i % 2 ? "odd" : "even", Material{"grey", glm::dvec3(0.5), glm::dvec3(0.0)}});
        soup.polygons.push_back({{first, first + 1, first + 2, first + 3}, static_cast<std::uint32_t>(i)});
    }
    const Scene built = build_scene(soup);
    int stopped = 0;
    for (const std::string& w : built.warnings)
        stopped += w.find("the search stopped there") != std::string::npos;
    EXPECT_EQ(stopped, 1);
    EXPECT_LE(lift_warnings(built), 4);  // even over odd, odd over even, even over even, odd over odd
    EXPECT_GE(lift_warnings(built), 1);
}

struct Solution {
    Scene scene;
    PatchMesh mesh;
    UniformTransport system;
    std::vector<glm::dvec3> b;
};

Solution solve(const std::string& path) {
    Solution s;
    s.scene = load_scene(asset(path));
    s.mesh = test::mesh(s.scene, 0.1);
    s.system = make_uniform_transport(s.scene, s.mesh, compute_form_factors(s.mesh, FormFactorOptions{}));
    auto solver = make_solver(SolverMethod::direct, s.system, SolverOptions{});
    EXPECT_TRUE(solver->step().converged());
    s.b.assign(solver->solution().begin(), solver->solution().end());
    return s;
}

double mean_radiosity(const Solution& s, const std::string& name) {
    const std::uint32_t k = surface_index(s.scene, name);
    double power = 0.0, area = 0.0;
    for (std::uint32_t i = s.mesh.surface_begin[k]; i < s.mesh.surface_begin[k + 1]; ++i) {
        power += s.mesh.patches[i].area * s.b[i].x;
        area += s.mesh.patches[i].area;
    }
    return power / area;
}

// The light is counted once: the emitted power is its area times E, nothing more. The ceiling behind it
// receives almost nothing (rays from there meet the light's back, except the few that leave sideways through
// the millimetre between them), every other surface is lit as in the room with the opening cut out, and the
// power balances.
TEST(Coplanar, TheRoomIsLitOnceAsIfTheOpeningWereCutOut) {
    const Solution lifted = solve("assets/hard/coplanar_light.obj");
    const Solution reference = solve("assets/hard/coplanar_light_reference.obj");
    const EnergyBalance balance = energy_balance(lifted.system, lifted.b);
    EXPECT_NEAR(balance.emitted.x, 0.16, 1e-12);  // 0.4 x 0.4 at E = 1
    EXPECT_NEAR(balance.absorbed.x + balance.escaped.x, balance.emitted.x, 5e-3 * balance.emitted.x);

    const std::uint32_t ceiling = surface_index(lifted.scene, "ceiling");
    const std::vector<glm::dvec3> whole = whole_patch_radiosity(lifted.system, lifted.mesh, lifted.b);
    double covered = 0.0, uncovered = 0.0;
    int covered_count = 0, uncovered_count = 0;
    for (std::uint32_t i = lifted.mesh.surface_begin[ceiling]; i < lifted.mesh.surface_begin[ceiling + 1];
         ++i) {
        const glm::dvec3 c = lifted.mesh.patches[i].centroid;
        const bool under_light = c.x > 0.3 && c.x < 0.7 && c.z > 0.3 && c.z < 0.7;
        // Averaged over the whole patch, as light arriving there is measured: the solution is the radiosity
        // of a patch's exposed part, and behind the light almost nothing of it is exposed.
        (under_light ? covered : uncovered) += whole[i].x;
        ++(under_light ? covered_count : uncovered_count);
    }
    ASSERT_EQ(covered_count, 16);
    covered /= covered_count;
    uncovered /= uncovered_count;
    std::printf("[ figures  ] ceiling behind the light: mean B %.3g, the rest of the ceiling %.3g\n", covered,
                uncovered);
    EXPECT_LT(covered, 0.01 * uncovered);

    for (const char* name : {"floor", "left", "right", "back", "front", "light"}) {
        const double a = mean_radiosity(lifted, name), b = mean_radiosity(reference, name);
        EXPECT_NEAR(a, b, 0.01 * b) << name;
    }
    // The reference's ceiling is the lifted one's uncovered part.
    EXPECT_NEAR(uncovered, mean_radiosity(reference, "ceiling"), 0.02 * uncovered);
}

}  // namespace
}  // namespace rad
