// assets/cornell_box.gltf renders as assets/cornell_box.obj does: the OBJ box's image is the glTF box's
// golden image, within the golden tolerance.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "golden_image.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

std::string render(const std::string& scene, const std::filesystem::path& out) {
    const auto result = test::run_radiosity({"render", scene, "--patch-size", "70", "--width", "256",
                                             "--height", "256", "--exposure", "0", "--out", out.string()});
    EXPECT_EQ(result.status, 0) << result.err;
    return out.string();
}

TEST(RenderGltf, CornellBoxMatchesTheObjBoxsImage) {
    test::TempDir dir;
    const std::string assets = std::string(RAD_SOURCE_DIR) + "/assets/";
    const std::string obj = render(assets + "cornell_box.obj", dir.path() / "obj.png");
    const std::string gltf = render(assets + "cornell_box.gltf", dir.path() / "gltf.png");
    const test::GoldenResult result = test::compare_with_image("cornell_box_gltf_256", obj, gltf);
    EXPECT_TRUE(result.passed) << result.message;
}

}  // namespace
}  // namespace rad
