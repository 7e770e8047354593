// A textured floor (assets/hard/textured_floor.obj: white on one half, black on the other): each patch
// reflects its own part of the image, so the room is lit as if the floor were two materials, and the energy
// balances for every transport.
#include <gtest/gtest.h>

#include <string>

#include "rad/scene/scene_loader.hpp"
#include "rad/transport/transport.hpp"
#include "solved_scene.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

const std::string kTexturedFloor = std::string(RAD_SOURCE_DIR) + "/assets/hard/textured_floor.obj";

// The same room with the floor cut into a white (Kd 0.8) and a black half, no texture.
Scene split_floor_room() {
    std::string obj = test::read_file_text(kTexturedFloor);
    const std::string textured = "o floor\nusemtl floor\nf 1/4 4/1 3/2 2/3\n";
    const auto at = obj.find(textured);
    EXPECT_NE(at, std::string::npos);
    obj.replace(at, textured.size(),
                "v 0.5 0 0\nv 0.5 0 1\no white\nusemtl white\nf 1 4 14 13\no black\nusemtl black\n"
                "f 13 14 3 2\n");
    std::string mtl = test::read_file_text(std::string(RAD_SOURCE_DIR) + "/assets/hard/textured_floor.mtl");
    mtl += "\nnewmtl white\nKd 0.8 0.8 0.8\nnewmtl black\nKd 0 0 0\n";
    static const test::TempDir dir;
    dir.write("textured_floor.mtl", mtl);
    return load_scene(dir.write("split.obj", obj));
}

// The area-weighted mean radiosity of a surface's patches whose centroids lie in x ∈ [x0, x1].
double mean_radiosity(const test::SolvedScene& s, const std::string& surface, double x0 = -1.0,
                      double x1 = 2.0) {
    double area = 0.0, power = 0.0;
    const PatchMesh& patches = *s.system.patches;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        if (s.scene.surfaces[patches.patches[i].surface].name != surface) continue;
        if (patches.patches[i].centroid.x < x0 || patches.patches[i].centroid.x > x1) continue;
        area += patches.patches[i].area;
        power += patches.patches[i].area * s.radiosity[i].y;
    }
    return power / area;
}

TEST(TexturedFloor, TheEnergyBalancesForEveryTransport) {
    for (Subdivision subdivision :
         {Subdivision::uniform, Subdivision::hierarchical, Subdivision::clustered}) {
        const auto s = test::solve_scene(load_scene(kTexturedFloor), subdivision);
        const EnergyBalance balance = energy_balance(*s->system.transport, s->radiosity);
        EXPECT_NEAR(balance.absorbed.y + balance.escaped.y, balance.emitted.y, 5e-3 * balance.emitted.y)
            << subdivision_name(subdivision) << ": absorbed " << balance.absorbed.y << ", escaped "
            << balance.escaped.y;
    }
}

TEST(TexturedFloor, LightsTheRoomAsAFloorOfTwoMaterialsWould) {
    const auto textured = test::solve_scene(load_scene(kTexturedFloor), Subdivision::uniform, 1.0 / 16);
    const auto split = test::solve_scene(split_floor_room(), Subdivision::uniform, 1.0 / 16);
    // The walls see the same floor but for the texels' filtering at the image's border and middle, which
    // moves 0.1 of albedo by a patch in 4 of 16 columns.
    const double walls = mean_radiosity(*textured, "walls");
    EXPECT_NEAR(walls, mean_radiosity(*split, "walls"), 0.01 * walls);
    // A textured floor of mean reflectance 0.4 reflects as much as the halves together.
    const double floor = mean_radiosity(*textured, "floor");
    const double halves = 0.5 * (mean_radiosity(*split, "white") + mean_radiosity(*split, "black"));
    EXPECT_NEAR(floor, halves, 0.02 * floor);
    // Each half of the textured floor is as bright as the material it stands for, away from the columns
    // the filtering blends.
    const double white = mean_radiosity(*split, "white", 0.07, 0.43);
    EXPECT_NEAR(mean_radiosity(*textured, "floor", 0.07, 0.43), white, 0.02 * white);
    EXPECT_NEAR(mean_radiosity(*textured, "floor", 0.57, 0.93), 0.0, 1e-12);
}

}  // namespace
}  // namespace rad
