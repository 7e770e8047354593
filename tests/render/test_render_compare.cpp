// `render --path-traced N` writes the path tracer's image from the same cameras; `render --compare REF.pfm`
// prints each image's error against a reference. A reference that cannot be compared is refused before any
// work, with one line naming --compare.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "rad/io/image_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

using test::run_radiosity;

const std::vector<std::string> kView = {"--width", "32",       "--height",
                                        "24",      "--camera", "0.5,0.5,0.9,0.3,0.4,0"};

test::CommandResult render(std::vector<std::string> args) {
    args.insert(args.begin(), "render");
    args.insert(args.end(), kView.begin(), kView.end());
    return run_radiosity(args);
}

// The two percentages of the --compare line for `out`.
std::pair<double, double> compared(const std::string& stdout_text, const std::string& out) {
    const std::size_t at = stdout_text.find(out + " against ");
    EXPECT_NE(at, std::string::npos) << stdout_text;
    if (at == std::string::npos) return {-1.0, -1.0};
    const std::size_t colon = stdout_text.find(": ", at);
    double block = -1.0, pixel = -1.0;
    std::sscanf(stdout_text.c_str() + colon, ": %lf %% per 8 x 8 block, %lf %% per pixel", &block, &pixel);
    return {block, pixel};
}

TEST(RenderCompare, ThePathTracedFurnaceShowsEOverOneMinusRhoOverPi) {
    test::TempDir dir;
    const std::string scene = test::write_furnace(dir);
    const std::string traced = (dir.path() / "traced.pfm").string();
    const auto result = render({scene, "--path-traced", "64", "--out", traced});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("path traced: 64 paths per pixel"), std::string::npos) << result.out;
    EXPECT_EQ(result.out.find("form factors"), std::string::npos) << result.out;  // no solve
    const Image image = read_image(traced);
    ASSERT_EQ(image.width, 32);
    double sum = 0.0;
    for (const glm::vec3& p : image.pixels) sum += p.g;
    EXPECT_NEAR(sum / static_cast<double>(image.pixels.size()) * std::numbers::pi, 2.0, 0.02);
}

TEST(RenderCompare, RadiosityAgainstThePathTracerAndAnImageAgainstItself) {
    test::TempDir dir;
    const std::string scene = test::write_furnace(dir);
    const std::string traced = (dir.path() / "traced.pfm").string();
    ASSERT_EQ(render({scene, "--path-traced", "64", "--out", traced}).status, 0);
    const std::string drawn = (dir.path() / "drawn.pfm").string();
    const auto result = render({scene, "--patch-size", "0.25", "--out", drawn, "--compare", traced});
    ASSERT_EQ(result.status, 0) << result.err;
    const auto [block, pixel] = compared(result.out, drawn);
    // Both show B / π = 2 / π; what is left is the path tracer's noise (roulette), well under 2 % per block.
    EXPECT_GE(block, 0.0);
    EXPECT_LT(block, 2.0);
    EXPECT_GE(pixel, block);
    const auto self = render(
        {scene, "--patch-size", "0.25", "--out", (dir.path() / "again.pfm").string(), "--compare", drawn});
    ASSERT_EQ(self.status, 0) << self.err;
    const auto [self_block, self_pixel] = compared(self.out, (dir.path() / "again.pfm").string());
    EXPECT_EQ(self_block, 0.0);
    EXPECT_EQ(self_pixel, 0.0);
}

TEST(RenderCompare, ReferencesThatCannotBeComparedAreRefusedBeforeAnyWork) {
    test::TempDir dir;
    const std::string scene = test::write_furnace(dir);
    const std::string small = (dir.path() / "small.pfm").string();
    ASSERT_EQ(run_radiosity(
                  {"render", scene, "--path-traced", "1", "--width", "8", "--height", "8", "--out", small})
                  .status,
              0);
    const std::string out = (dir.path() / "x.pfm").string();
    const struct {
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {{scene, "--out", out, "--compare", small}, "--compare: " + small + " is 8x8, the images are 32x24"},
        {{scene, "--out", out, "--compare", (dir.path() / "none.pfm").string()}, "none.pfm"},
        {{scene, "--out", out, "--compare", (dir.path() / "ref.png").string()}, "a reference must be a .pfm"},
        {{scene, "--out", out, "--path-traced", "4", "--export", (dir.path() / "m.ply").string()},
         "--export: writes radiosity's mesh; not with --path-traced"},
    };
    for (const auto& c : cases) {
        const auto result = render(c.args);
        EXPECT_EQ(result.status, 2) << c.message;
        EXPECT_NE(result.err.find(c.message), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_EQ(result.out.find("form factors"), std::string::npos) << result.out;
        EXPECT_FALSE(std::filesystem::exists(out));
    }
}

}  // namespace
}  // namespace rad
