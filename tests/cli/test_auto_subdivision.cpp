// `--subdivision auto`, the default: uniform patches for a scene of few patches, clustering for one of many
// faces, and the furnace's closed form either way.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "rad/transport/scene_transport.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

using nlohmann::json;
using test::run_radiosity;

json solve(const std::vector<std::string>& arguments, const test::TempDir& dir) {
    const std::string out = (dir.path() / "out.json").string();
    std::vector<std::string> command = {"solve"};
    command.insert(command.end(), arguments.begin(), arguments.end());
    command.insert(command.end(), {"--json", out});
    const auto result = run_radiosity(command);
    EXPECT_EQ(result.status, 0) << result.err;
    std::ifstream in(out);
    return json::parse(in);
}

TEST(AutoSubdivision, TheCornellBoxGetsUniformPatches) {
    test::TempDir dir;
    const json doc = solve({"builtin:cornell", "--rays", "256"}, dir);
    EXPECT_EQ(doc.at("stats").at("transport").at("kind"), "uniform");
    EXPECT_LE(doc.at("patches").size(), kAutomaticUniformPatches);
}

// builtin:furnace-12k has more than kAutomaticUniformPatches faces: clustering, with B = E / (1 − ρ) = 2.
TEST(AutoSubdivision, AFurnaceOfManyFacesIsClusteredAndExact) {
    test::TempDir dir;
    const json doc = solve({"builtin:furnace-12k"}, dir);
    EXPECT_EQ(doc.at("stats").at("transport").at("kind"), "clustered");
    double worst = 0.0;
    for (const json& p : doc.at("patches"))
        worst = std::max(worst, std::abs(p.at("radiosity").at(0).get<double>() / 2.0 - 1.0));
    EXPECT_LT(worst, 5e-3);
    const json& energy = doc.at("stats").at("energy");
    const double emitted = energy.at("emitted").at(0), absorbed = energy.at("absorbed").at(0),
                 escaped = energy.at("escaped").at(0);
    EXPECT_NEAR((absorbed + escaped) / emitted, 1.0, 5e-3);
}

TEST(AutoSubdivision, AnExplicitSubdivisionIsKept) {
    EXPECT_EQ(choose_subdivision(Subdivision::hierarchical, 1), Subdivision::hierarchical);
    EXPECT_EQ(choose_subdivision(Subdivision::uniform, 10 * kAutomaticUniformPatches), Subdivision::uniform);
    EXPECT_EQ(choose_subdivision(Subdivision::automatic, kAutomaticUniformPatches), Subdivision::uniform);
    EXPECT_EQ(choose_subdivision(Subdivision::automatic, kAutomaticUniformPatches + 1),
              Subdivision::clustered);
}

}  // namespace
}  // namespace rad
