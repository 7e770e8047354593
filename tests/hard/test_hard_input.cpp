// Hard case: materials that break the radiosity equation. Emission that is NaN, infinite or negative poisons
// every patch it reaches: each is refused at load, before any work, with exit status 2 and one line naming
// the .mtl file, the line and the value (assets/hard/reject_*). Reflectance ≥ 1 makes light that never
// decays, but real files write white as Kd 1: it is clamped to kMaxReflectance with one warning
// (assets/hard/clamp_*).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "expect_input_error.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
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

// Kd 1 and Kd 1.5 on a closed cube that emits E = 1: one warning each, and the cube is the furnace at
// ρ = 0.99, B = E / (1 − 0.99) = 100 on every patch (direct solve, hemisphere factors of a closed scene).
TEST(ClampedMaterials, ReflectanceOfOneOrMoreBecomesTheFurnaceAtTheMaximum) {
    ASSERT_EQ(kMaxReflectance, 0.99);
    for (const std::string name : {"clamp_kd_one", "clamp_kd_above_one"}) {
        SCOPED_TRACE(name);
        const Scene scene = load_scene(asset(name + ".obj"));
        ASSERT_EQ(scene.warnings.size(), 1u);
        EXPECT_NE(scene.warnings[0].find("1 material(s) reflect 1 or more"), std::string::npos)
            << scene.warnings[0];
        EXPECT_NE(scene.warnings[0].find("clamped to 0.99"), std::string::npos) << scene.warnings[0];
        const PatchMesh patches = build_patches(scene, MeshingOptions{.patch_size = 0.25});
        const UniformTransport system =
            make_uniform_transport(scene, patches, compute_form_factors(patches, FormFactorOptions{}));
        SolverOptions options;
        auto solver = make_solver(SolverMethod::direct, system, options);
        while (!solver->report().finished()) solver->step();
        ASSERT_EQ(system.size(), 96u);
        for (std::size_t i = 0; i < system.size(); ++i) {
            EXPECT_DOUBLE_EQ(system.reflectance[i].x, 0.99);
            EXPECT_NEAR(solver->solution()[i].y, 100.0, 0.1) << "patch " << i;
        }
    }
}

// From the command line the clamp is one warning line, and the run succeeds.
TEST(ClampedMaterials, TheCommandWarnsOnceAndSolves) {
    test::TempDir dir;
    const std::string json = (dir.path() / "out.json").string();
    const test::CommandResult result =
        test::run_radiosity({"solve", asset("clamp_kd_one.obj"), "--patch-size", "0.5", "--json", json});
    ASSERT_EQ(result.status, 0) << result.err;
    std::size_t warnings = 0;
    for (std::size_t at = result.err.find("warning:"); at != std::string::npos;
         at = result.err.find("warning:", at + 1))
        ++warnings;
    EXPECT_EQ(warnings, 1u) << result.err;
    EXPECT_NE(
        result.err.find("clamp_kd_one.obj: 1 material(s) reflect 1 or more (largest 1, first 'sloppy')"),
        std::string::npos)
        << result.err;
}

}  // namespace
}  // namespace rad
