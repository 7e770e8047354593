// Hard case: materials that break the radiosity equation. Reflectance ≥ 1 makes light that never decays (or
// grows); emission that is NaN, infinite or negative poisons every patch it reaches. Each is refused at load,
// before any work, with exit status 2 and one line naming the .mtl file, the line and the value
// (assets/hard/reject_*).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "expect_input_error.hpp"
#include "rad/scene/scene_loader.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

struct Rejected {
    std::string scene;    // in assets/hard, without .obj
    std::string message;  // what the one line must say after "NAME.mtl:LINE: "
    int line;             // the .mtl line of the offending value
};

const std::vector<Rejected>& rejected() {
    static const std::vector<Rejected> all = {
        {"reject_kd_one", "reflectance (Kd) '1' must lie in [0, 1)", 3},
        {"reject_kd_above_one", "reflectance (Kd) '1.5' must lie in [0, 1)", 3},
        {"reject_ke_nan", "emission (Ke) 'nan' must be finite and not negative", 4},
        {"reject_ke_inf", "emission (Ke) 'inf' must be finite and not negative", 4},
        {"reject_ke_negative", "emission (Ke) '-0.5' must be finite and not negative", 4},
    };
    return all;
}

std::string asset(const std::string& name) {
    return std::string(RAD_SOURCE_DIR) + "/assets/hard/" + name;
}

TEST(RejectedMaterials, TheLoaderThrowsNamingTheMtlLineAndValue) {
    for (const Rejected& r : rejected()) {
        SCOPED_TRACE(r.scene);
        test::expect_input_error(load_scene, asset(r.scene + ".obj"),
                                 {r.scene + ".mtl:" + std::to_string(r.line) + ": ", r.message});
    }
}

// Every command refuses them the same way, writing nothing.
TEST(RejectedMaterials, EveryCommandExitsWithStatus2AndOneLine) {
    test::TempDir dir;
    const std::string json = (dir.path() / "out.json").string();
    const std::string png = (dir.path() / "out.png").string();
    for (const Rejected& r : rejected()) {
        for (const std::vector<std::string>& command :
             {std::vector<std::string>{"info"}, {"solve", "--json", json}, {"render", "--out", png}}) {
            std::vector<std::string> args = command;
            args.push_back(asset(r.scene + ".obj"));
            const test::CommandResult result = test::run_radiosity(args);
            SCOPED_TRACE(r.scene + " " + command[0]);
            EXPECT_EQ(result.status, 2);
            EXPECT_NE(result.err.find(r.scene + ".mtl:" + std::to_string(r.line) + ": "), std::string::npos)
                << result.err;
            EXPECT_NE(result.err.find(r.message), std::string::npos) << result.err;
            EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        }
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// A value too large for a double is refused as well, not read as infinity.
TEST(RejectedMaterials, EmissionBeyondTheDoubleRangeIsRefused) {
    test::TempDir dir;
    dir.write("huge.mtl", "newmtl huge\nKd 0.5 0.5 0.5\nKe 1e999 1 1\n");
    const std::string obj =
        dir.write("huge.obj", "mtllib huge.mtl\nv 0 0 0\nv 0 0 1\nv 1 0 1\nusemtl huge\nf 1 2 3\n");
    test::expect_input_error(load_scene, obj, {"huge.mtl:3:", "1e999"});
}

}  // namespace
}  // namespace rad
