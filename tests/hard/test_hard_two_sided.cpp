// Hard case: two-sided surfaces. A two-sided material (glTF `doubleSided`) reflects and emits on both sides,
// and back-to-back faces in a file (assets/hard/back_to_back.obj) are read as one two-sided surface: each
// side has its own elements, light on one side never reaches the other, and the energy balances.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/scene_transport.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

using Solved = test::SolvedScene;

// Area-weighted mean radiosity (green channel) of the elements of the surfaces with this name.
double mean_radiosity(const Solved& s, const std::string& name) {
    double power = 0.0, area = 0.0;
    const PatchMesh& elements = *s.system.patches;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (s.scene.surfaces[elements.patches[i].surface].name != name) continue;
        power += s.system.transport->area[i] * s.radiosity[i].y;
        area += s.system.transport->area[i];
    }
    EXPECT_GT(area, 0.0) << name;
    return area > 0.0 ? power / area : 0.0;
}

Scene back_to_back_room() {
    return load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/back_to_back.obj");
}

TEST(BackToBackFaces, AreReadAsOneTwoSidedSurfaceWithAWarning) {
    const Scene scene = back_to_back_room();
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("1 pair(s) of back-to-back faces"), std::string::npos)
        << scene.warnings[0];
    for (const Surface& s : scene.surfaces)
        EXPECT_EQ(s.back_to_back, s.name == "panel_a" || s.name == "panel_b") << s.name;
}

// A closed room: nothing escapes, so everything emitted is absorbed, within 0.5 % for each transport that
// keeps the accounting (hierarchical links lose some light at their defaults; docs/subdivision.md).
TEST(BackToBackFaces, TheEnergyOfAClosedRoomBalances) {
    for (Subdivision subdivision : {Subdivision::uniform, Subdivision::adaptive, Subdivision::clustered}) {
        const auto s = test::solve_scene(back_to_back_room(), subdivision);
        const EnergyBalance balance = energy_balance(*s->system.transport, s->radiosity);
        EXPECT_NEAR(balance.absorbed.y + balance.escaped.y, balance.emitted.y, 5e-3 * balance.emitted.y)
            << subdivision_name(subdivision) << ": absorbed " << balance.absorbed.y << ", escaped "
            << balance.escaped.y;
        EXPECT_LT(balance.escaped.y, 5e-3 * balance.emitted.y) << subdivision_name(subdivision);
    }
}

// The panel's side that faces the light (red, ρ = 0.2 in green) is lit directly; the other side (green,
// ρ = 0.7) sees only the half of the room the panel shades, so it receives less light, but some.
TEST(BackToBackFaces, EachSideIsLitByWhatItFaces) {
    const auto s = test::solve_scene(back_to_back_room(), Subdivision::uniform);
    const double lit = mean_radiosity(*s, "panel_a") / 0.2, shaded = mean_radiosity(*s, "panel_b") / 0.7;
    EXPECT_GT(shaded, 0.1 * lit);
    EXPECT_GT(lit, 2.0 * shaded);
}

// A unit panel at z = 0 and a light of the same size at z = 1 facing it; `two_sided` says what the panel is.
PolygonSoup panel_under_light(bool two_sided, bool light_two_sided) {
    PolygonSoup soup;
    soup.source = "panel";
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    Material panel{.name = "panel", .reflectance = glm::dvec3(0.6), .two_sided = two_sided};
    Material light{.name = "light",
                   .reflectance = glm::dvec3(0.0),
                   .emission = glm::dvec3(1.0),
                   .two_sided = light_two_sided};
    soup.groups = {{"panel", panel}, {"light", light}};
    soup.polygons = {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}};  // the panel faces +z, the light −z
    return soup;
}

TEST(TwoSidedMaterial, HasABackOfItsOwnThatTheLightNeverReaches) {
    const Scene scene = build_scene(panel_under_light(true, false));
    ASSERT_EQ(scene.surfaces.size(), 3u);
    EXPECT_EQ(scene.surfaces[0].name, "panel");
    EXPECT_EQ(scene.surfaces[1].name, "panel (back)");
    EXPECT_TRUE(scene.surfaces[0].back_to_back && scene.surfaces[1].back_to_back);
    EXPECT_FALSE(scene.surfaces[2].back_to_back);
    EXPECT_DOUBLE_EQ(surface_area(scene.surfaces[1].mesh), 1.0);

    for (Subdivision subdivision : {Subdivision::uniform, Subdivision::clustered}) {
        const auto two = test::solve_scene(build_scene(panel_under_light(true, false)), subdivision, 0.25);
        const auto one = test::solve_scene(build_scene(panel_under_light(false, false)), subdivision, 0.25);
        const double front = mean_radiosity(*two, "panel");
        // The lit side gets what a one-sided panel gets: the light, and nothing lost to its own back.
        EXPECT_NEAR(front, mean_radiosity(*one, "panel"), 1e-3 * front) << subdivision_name(subdivision);
        EXPECT_GT(front, 0.1);
        EXPECT_EQ(mean_radiosity(*two, "panel (back)"), 0.0) << subdivision_name(subdivision);
    }
}

// A two-sided light between two panels lights both alike; a one-sided one only the panel it faces.
TEST(TwoSidedMaterial, EmitsOnBothSides) {
    PolygonSoup soup = panel_under_light(false, true);
    soup.positions.insert(soup.positions.end(), {{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}});
    soup.groups.push_back({"upper", soup.groups[0].material});
    soup.polygons.push_back({{8, 11, 10, 9}, 2});  // facing −z, down at the light
    const auto s = test::solve_scene(build_scene(soup), Subdivision::uniform, 0.25);
    const double lower = mean_radiosity(*s, "panel"), upper = mean_radiosity(*s, "upper");
    EXPECT_GT(lower, 0.1);
    EXPECT_NEAR(upper, lower, 0.02 * lower);
    const double light = mean_radiosity(*s, "light (back)");
    EXPECT_GT(light, 1.0);  // E = π plus the panel's light reflected back at it
}

// At the ray level: a ray that reaches a back-to-back patch's back goes on to the other side's front; a
// one-sided back blocks.
TEST(BackToBackFaces, RaysPassTheBackOfOneSideAndMeetTheOther) {
    for (bool two_sided : {false, true}) {
        const Scene scene = build_scene(panel_under_light(two_sided, false));
        const PatchMesh patches = build_patches(scene, MeshingOptions{.patch_size = 1.0});
        const RayScene rays(patches);
        const std::vector<Ray> from_below{Ray{{0.3, 0.4, -1.0}, 0.0f, {0.0, 0.0, 1.0}, 10.0f}};
        std::vector<RayHit> hit(1);
        rays.intersect(from_below, hit);
        if (!two_sided) {
            EXPECT_EQ(hit[0].patch, RayHit::kBackFace);
            continue;
        }
        ASSERT_LT(hit[0].patch, patches.size());
        EXPECT_EQ(scene.surfaces[patches.patches[hit[0].patch].surface].name, "panel (back)");
        EXPECT_NEAR(hit[0].t, 1.0f, 1e-6f);
        std::vector<std::uint8_t> blocked(1);
        rays.occluded(from_below, blocked);
        EXPECT_EQ(blocked[0], 1);  // a two-sided surface still casts shadows
    }
}

}  // namespace
}  // namespace rad
