// The OSMesa fallback: forced, it renders the golden Cornell box; automatic, it takes over when EGL has no
// driver (glvnd is pointed at a vendor file that does not exist).
#include <gtest/gtest.h>

#include <filesystem>

#include "golden_image.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

// The golden image is at exposure 0, as auto exposure has its own tests (test_render_auto_exposure.cpp).
const std::vector<std::string> kCornell256 = {
    "render", "builtin:cornell", "--patch-size", "70",         "--width",
    "256",    "--height",        "256",          "--exposure", "0"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// Runs radiosity with EGL unable to find any driver.
test::CommandResult run_without_egl_driver(const std::vector<std::string>& args) {
    std::vector<std::string> command = {"__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent/egl_vendor.json",
                                        RAD_BINARY};
    command.insert(command.end(), args.begin(), args.end());
    return test::run_program("env", command);
}

std::filesystem::path golden_path() {
    return std::filesystem::path(RAD_GOLDEN_DIR) / "cornell_256.png";
}

TEST(RenderOsmesa, ForcedOsmesaRendersTheGoldenCornellBox) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cornell.png").string();
    const test::CommandResult result =
        test::run_radiosity(with(kCornell256, {"--gl-platform", "osmesa", "--out", out}));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("(OSMesa: OpenGL"), std::string::npos) << result.out;
    const test::GoldenResult golden =
        test::compare_with_image("cornell_256_osmesa", golden_path().string(), out);
    EXPECT_TRUE(golden.passed) << golden.message;
}

TEST(RenderOsmesa, AutomaticFallsBackToOsmesaWhenEglHasNoDriver) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cornell.png").string();
    const test::CommandResult result = run_without_egl_driver(with(kCornell256, {"--out", out}));
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("(OSMesa: OpenGL"), std::string::npos) << result.out;
    const test::GoldenResult golden =
        test::compare_with_image("cornell_256_fallback", golden_path().string(), out);
    EXPECT_TRUE(golden.passed) << golden.message;
}

TEST(RenderOsmesa, EglAloneWithoutADriverFailsClearlyAndWritesNothing) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cornell.png").string();
    const test::CommandResult result =
        run_without_egl_driver(with(kCornell256, {"--gl-platform", "egl", "--out", out}));
    EXPECT_EQ(result.status, 1);
    EXPECT_NE(result.err.find("no headless OpenGL 3.3 context: EGL"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(RenderOsmesa, AnUnknownPlatformIsAnOptionError) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cornell.png").string();
    const test::CommandResult result =
        test::run_radiosity(with(kCornell256, {"--gl-platform", "glx", "--out", out}));
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("--gl-platform"), std::string::npos) << result.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rad
