// Hard case: light leaks. The leak suite (assets/hard/leak_*.obj, written by scripts/leak_rooms.py) builds a
// closed 1 m interior the ways modelling tools and IFC exporters build rooms: one box of inward faces, wall
// slabs touching, overlapping, meeting only along edges, standing on a floor that runs under them, a room
// beside a lit one, legs and a beam through the slabs. Lit from outside (a sky) or from the neighbouring
// room, no element whose front looks into the interior may receive light, for any subdivision.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/reference/leak_rooms.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/transport/transport.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

Scene leak_scene(const LeakRoom& room) {
    Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/" + room.name + ".obj");
    if (room.sky) scene.sky = Sky{Sky::Kind::uniform, glm::dvec3(1.0)};
    return scene;
}

Leak measure(const test::SolvedScene& s, const BoundingBox& dark) {
    return measure_leak(s.scene, *s.system.patches, s.radiosity, dark);
}

class LeakSuite : public ::testing::TestWithParam<Subdivision> {};

// Clustering meshes its base patches at 4 × the uniform size, as the program does (its base_patch_scale).
double base_patch_size(const Scene& scene, Subdivision subdivision) {
    return subdivision == Subdivision::clustered ? 4.0 * default_patch_size(scene) : 0.0;
}

// At most 1e-6 of the light outside reaches the interior (rounding). Not yet for clustering's dark room
// beside a lit one, which gets 2e-4 of the lit room's light (docs/hard-cases.md): held below 1e-3.
TEST_P(LeakSuite, NoLightReachesAClosedInterior) {
    for (const LeakRoom& c : leak_rooms()) {
        Scene scene = leak_scene(c);
        const double size = base_patch_size(scene, GetParam());
        // As the program sets them: the lamps' light aimed at by shadow rays.
        TransportSettings settings;
        settings.subdivision = GetParam();
        settings.form_factors.emitting_surfaces = emitting_surfaces(scene);
        settings.form_factors.emitted_luminance =
            emitted_luminance(scene, settings.form_factors.emitting_surfaces);
        const auto s = test::solve_scene(std::move(scene), settings, size);
        const Leak leak = measure(*s, c.interior);
        const bool open = GetParam() == Subdivision::clustered && c.name == "leak_two_rooms";
        // Energy balances: what the lamp and the sky bring is absorbed or escapes.
        const EnergyBalance e = energy_balance(*s->system.transport, s->radiosity);
        EXPECT_NEAR(e.absorbed.y + e.escaped.y, e.emitted.y + e.outside.y, 5e-3 * (e.emitted.y + e.outside.y))
            << c.name;
        EXPECT_GE(leak.inside, 6u) << c.name;
        EXPECT_GT(leak.lit_mean, 0.0) << c.name;
        EXPECT_LE(leak.worst_inside, (open ? 1e-3 : 1e-6) * leak.lit_mean)
            << c.name << ": the interior gets " << leak.worst_inside / leak.lit_mean
            << " of the light outside";
    }
}

// Not yet closed: clustering over base patches of the uniform size (a quarter of its default) lets in up to
// 12 % (docs/hard-cases.md): a link into a cluster that holds both sides of a wall slab gives its light to
// every surface inside facing the source, and a cluster sends the mean radiosity of all its surfaces. Held
// below 15 %.
TEST(LeakSuiteClustered, FinerBasePatchesLetInLittle) {
    for (const LeakRoom& c : leak_rooms()) {
        const auto s = test::solve_scene(leak_scene(c), Subdivision::clustered);
        const Leak leak = measure(*s, c.interior);
        EXPECT_LE(leak.worst_inside, 0.15 * leak.lit_mean)
            << c.name << ": the interior gets " << leak.worst_inside / leak.lit_mean
            << " of the light outside";
    }
}

INSTANTIATE_TEST_SUITE_P(EverySubdivision, LeakSuite,
                         ::testing::Values(Subdivision::uniform, Subdivision::adaptive,
                                           Subdivision::hierarchical, Subdivision::clustered));

// Parts of faces inside another solid are cut off and dropped: the floor under the four wall slabs, the
// legs' stretch inside the floor slab, the beam's inside the wall. What stays is the area outside.
TEST(SolidCuts, PartsInsideSolidsAreDropped) {
    const Scene under = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/hard/leak_floor_under.obj");
    double floor_area = 0.0;
    for (const Surface& surface : under.surfaces)
        if (surface.name == "floor") floor_area += surface_area(surface.mesh);
    // A 3 × 3 floor less the walls' footprints: 2 × (1.2 × 0.1) + 2 × (1 × 0.1).
    EXPECT_NEAR(floor_area, 9.0 - 0.44, 1e-9);
    const bool warned = std::any_of(under.warnings.begin(), under.warnings.end(), [](const std::string& w) {
        return w.find("reach into closed solids") != std::string::npos;
    });
    EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace rad
