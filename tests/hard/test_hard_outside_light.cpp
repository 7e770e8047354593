// Hard case: light from outside the scene. A sky at infinity meets every ray that leaves the scene and a sun
// lights what its shadow rays reach: closed forms on an open plate, the energy of a room lit through its
// window (assets/hard/window_room.obj) for every transport, and that room against the path tracer, which
// traces the same sky and sun.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "rad/reference/path_tracer.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/scene_transport.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

using Solved = test::SolvedScene;

// A unit plate of ρ = 0.5 in the plane through the origin with this normal, alone under the sky.
Scene plate(const glm::dvec3& normal) {
    PolygonSoup soup;
    soup.source = "plate";
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 u =
        glm::normalize(glm::cross(std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0), n));
    const glm::dvec3 v = glm::cross(n, u);
    soup.positions = {-0.5 * u - 0.5 * v, 0.5 * u - 0.5 * v, 0.5 * u + 0.5 * v, -0.5 * u + 0.5 * v};
    soup.groups = {{"plate", Material{.name = "plate", .reflectance = glm::dvec3(0.5)}}};
    soup.polygons = {{{0, 1, 2, 3}, 0}};
    Scene scene = build_scene(soup);
    scene.warnings.clear();
    return scene;
}

double mean_radiosity(const Solved& s) {
    double power = 0.0, area = 0.0;
    for (std::size_t i = 0; i < s.system.transport->size(); ++i) {
        power += s.system.transport->area[i] * s.radiosity[i].x;
        area += s.system.transport->area[i];
    }
    return power / area;
}

// A uniform sky of radiance L lights a plate facing any way with irradiance π L: B = ρ π L, exactly, as every
// ray leaves the scene. The overcast sky, L = Lz (1 + 2 cos θ) / 3 above the horizon, gives an upward plate
// 7π/9 Lz. A sun of irradiance E at angle θ to the normal gives ρ E cos θ.
TEST(OutsideLight, AnOpenPlateGetsTheClosedForms) {
    for (const glm::dvec3& normal : {glm::dvec3(0, 1, 0), glm::dvec3(1, -2, 0.5)}) {
        Scene scene = plate(normal);
        scene.sky = Sky{Sky::Kind::uniform, glm::dvec3(2.0)};
        const auto s = test::solve_scene(std::move(scene), Subdivision::uniform, 0.25);
        for (const glm::dvec3& b : s->radiosity) EXPECT_NEAR(b.x, 0.5 * std::numbers::pi * 2.0, 1e-12);
    }
    Scene overcast = plate({0, 1, 0});
    overcast.sky = Sky{Sky::Kind::overcast, glm::dvec3(1.0)};
    const auto o = test::solve_scene(std::move(overcast), Subdivision::uniform, 0.25);
    EXPECT_NEAR(mean_radiosity(*o), 0.5 * 7.0 * std::numbers::pi / 9.0, 1e-3);

    Scene sunny = plate({0, 0, 1});
    sunny.sun = Sun{glm::normalize(glm::dvec3(0, 1, 1)), glm::dvec3(3.0)};
    const auto s = test::solve_scene(std::move(sunny), Subdivision::uniform, 0.25);
    for (const glm::dvec3& b : s->radiosity) EXPECT_NEAR(b.x, 0.5 * 3.0 * std::sqrt(0.5), 1e-12);
    Scene behind = plate({0, 0, -1});
    behind.sun = Sun{glm::normalize(glm::dvec3(0, 1, 1)), glm::dvec3(3.0)};
    EXPECT_EQ(mean_radiosity(*test::solve_scene(std::move(behind), Subdivision::uniform, 0.25)), 0.0);
}

Scene window_room(bool sky, bool sun) {
    Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/window_room.obj");
    if (sky) scene.sky = Sky{Sky::Kind::overcast, glm::dvec3(1.0)};
    // Through the window, low enough to reach the floor.
    if (sun) scene.sun = Sun{glm::normalize(glm::dvec3(0.2, 0.5, -1.0)), glm::dvec3(10.0)};
    return scene;
}

// What comes in through the window is absorbed or leaves through it again.
TEST(OutsideLight, TheEnergyOfARoomLitThroughItsWindowBalances) {
    for (Subdivision subdivision : {Subdivision::uniform, Subdivision::adaptive, Subdivision::clustered}) {
        const auto s = test::solve_scene(window_room(true, true), subdivision);
        const EnergyBalance balance = energy_balance(*s->system.transport, s->radiosity);
        EXPECT_EQ(balance.emitted.y, 0.0);
        EXPECT_GT(balance.outside.y, 0.0);
        EXPECT_NEAR(balance.absorbed.y + balance.escaped.y, balance.outside.y, 5e-3 * balance.outside.y)
            << subdivision_name(subdivision) << ": in " << balance.outside.y << ", absorbed "
            << balance.absorbed.y << ", escaped " << balance.escaped.y;
        // Each element gets outside light of its own; the floor under the window has the sun.
        EXPECT_EQ(s->system.transport->outside.size(), s->system.transport->size());
    }
}

// A uniform sky of radiance L outside a window of area A sends π L A through it, all of which lands on the
// room's walls first: Σ A_i H_out,i = π L A, whatever the room.
TEST(OutsideLight, TheSkyThroughAWindowBringsInPiLA) {
    Scene scene = window_room(false, false);
    scene.sky = Sky{Sky::Kind::uniform, glm::dvec3(2.0)};
    const auto s = test::solve_scene(std::move(scene), Subdivision::uniform, 0.5);
    const Transport& t = *s->system.transport;
    double flux = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) flux += t.area[i] * t.outside[i].x;
    EXPECT_NEAR(flux, std::numbers::pi * 2.0, 0.01 * std::numbers::pi * 2.0);
}

// The area-weighted RMS of a over patches, relative to that of b.
double relative_rms(const PatchMesh& patches, std::span<const glm::dvec3> a, std::span<const glm::dvec3> b) {
    double numerator = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        numerator += patches.patches[i].area * glm::dot(a[i], a[i]);
        norm += patches.patches[i].area * glm::dot(b[i], b[i]);
    }
    return std::sqrt(numerator / norm);
}

double rms_difference(const PatchMesh& patches, std::span<const glm::dvec3> a,
                      std::span<const glm::dvec3> b) {
    std::vector<glm::dvec3> d(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
    return relative_rms(patches, d, b);
}

// The room against the path tracer on the same patches: the sky through the window (bounces that leave
// the scene), the sun (shadow rays), and their interreflections. Both are Monte Carlo estimates, so the
// patches differ by what their noise explains: the path tracer's from its standard errors, the radiosity's
// from two solutions of different seeds (their difference is √2 times one's noise). Each wall's power, where
// the noise averages out, agrees within 3 % and three of the path tracer's standard errors.
TEST(OutsideLight, TheWindowRoomAgreesWithThePathTracer) {
    for (const auto& [sky, sun] : {std::pair{true, false}, std::pair{false, true}}) {
        const auto s = test::solve_scene(window_room(sky, sun), Subdivision::uniform, 0.5);
        const auto other_seed = test::solve_scene(window_room(sky, sun), Subdivision::uniform, 0.5, 2);
        const PathTracer tracer(s->scene, s->patches, {.seed = 5});
        const std::vector<Estimate> traced = tracer.patch_radiosity(8000);
        std::vector<glm::dvec3> reference, error;
        for (const Estimate& e : traced) {
            reference.push_back(e.mean);
            error.push_back(e.standard_error);
        }
        const double traced_noise = relative_rms(s->patches, error, reference);
        const double own_noise =
            rms_difference(s->patches, s->radiosity, other_seed->radiosity) / std::numbers::sqrt2;
        const double difference = rms_difference(s->patches, s->radiosity, reference);
        const double explained = std::hypot(traced_noise, own_noise);
        // What constant patches leave: the path tracer's light varies within a patch, not theirs.
        constexpr double kDiscretization = 0.02;
        std::cout << (sky ? "sky" : "sun") << ": " << s->patches.size()
                  << " patches, relative RMS difference " << difference << ", path tracer noise "
                  << traced_noise << ", radiosity noise " << own_noise << "\n";
        EXPECT_LT(difference, 1.3 * std::hypot(explained, kDiscretization));
        EXPECT_LT(own_noise, 0.1);
        for (std::size_t k = 0; k < s->scene.surfaces.size(); ++k) {
            double solved = 0.0, path_traced = 0.0, variance = 0.0;
            for (std::uint32_t i = s->patches.surface_begin[k]; i < s->patches.surface_begin[k + 1]; ++i) {
                const double a = s->patches.patches[i].area;
                solved += a * s->radiosity[i].x;
                path_traced += a * reference[i].x;
                variance += a * a * error[i].x * error[i].x;
            }
            EXPECT_NEAR(solved, path_traced, 0.03 * path_traced + 3.0 * std::sqrt(variance))
                << s->scene.surfaces[k].name;
        }
    }
}

}  // namespace
}  // namespace rad
