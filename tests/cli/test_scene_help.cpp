// Every command's help names every built-in scene (view's once left out white-room).
#include <gtest/gtest.h>

#include "rad/scene/builtin_scenes.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

TEST(SceneHelp, EveryCommandNamesEveryBuiltinScene) {
    for (const char* command : {"view", "render", "solve", "info"}) {
        const test::CommandResult result = test::run_program(RAD_BINARY, {command, "--help"});
        ASSERT_EQ(result.status, 0) << command << ": " << result.err;
        for (const BuiltinSceneInfo& scene : builtin_scenes())
            EXPECT_NE(result.out.find(scene.name), std::string::npos)
                << command << " --help omits " << scene.name;
    }
}

}  // namespace
}  // namespace rad
