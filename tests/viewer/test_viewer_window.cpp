// The real viewer window under Xvfb: opens on the Cornell box, takes 1 and then 3 solver steps in scripted
// runs, and saves what it shows. Light reaches the ceiling only by bouncing off the floor and walls (the lamp
// is flush with it and faces down), so after one bounce the ceiling is black and after three it is lit.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>

#include "rad/io/image_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 480;

struct Region {
    double left, right, top, bottom;  // fractions of the width and height, top row first
};

// A band just below the top edge, a quarter of the width from the left: ceiling, away from the lamp.
constexpr Region kCeiling{0.20, 0.30, 0.04, 0.10};
// The middle of the lamp, which hangs from the ceiling's centre.
constexpr Region kLamp{0.47, 0.53, 0.135, 0.15};

double mean_brightness(const Image& image, const Region& region) {
    double sum = 0.0;
    int count = 0;
    for (int y = int(region.top * image.height); y < int(region.bottom * image.height); ++y) {
        for (int x = int(region.left * image.width); x < int(region.right * image.width); ++x) {
            const glm::vec3& p = image.at(x, y);
            sum += (p.r + p.g + p.b) / 3.0;
            ++count;
        }
    }
    return sum / count;
}

// Runs the window through a scripted session of `steps` solver steps and returns its screenshot.
Image screenshot_after(const std::string& xvfb_run, int steps, const std::filesystem::path& folder) {
    const std::string path = (folder / ("steps-" + std::to_string(steps) + ".png")).string();
    const test::CommandResult result = test::run_program(
        xvfb_run, {"-a", "-s", "-screen 0 1024x768x24", RAD_BINARY, "view", "builtin:cornell", "--patch-size",
                   "70", "--width", std::to_string(kWidth), "--height", std::to_string(kHeight), "--steps",
                   std::to_string(steps), "--screenshot", path, "--exit"});
    EXPECT_EQ(result.status, 0) << "stdout:\n" << result.out << "stderr:\n" << result.err;
    EXPECT_NE(result.out.find("wrote " + path), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("step " + std::to_string(steps) + ";"), std::string::npos) << result.out;
    if (!std::filesystem::exists(path)) {
        ADD_FAILURE() << "no screenshot at " << path;
        return {};
    }
    return read_image(path);
}

TEST(ViewerWindow, ScreenshotsAfterOneAndThreeBouncesDifferWhereIndirectLightReaches) {
    const std::string xvfb_run = test::find_in_path("xvfb-run");
    ASSERT_FALSE(xvfb_run.empty()) << "xvfb-run not found: scripts/install-deps.sh (run by the test command) "
                                      "installs the xvfb package that provides it";
    const test::TempDir folder;
    const Image one = screenshot_after(xvfb_run, 1, folder.path());
    const Image three = screenshot_after(xvfb_run, 3, folder.path());
    // The screenshot is the 3D view, beside the panel docked at the window's left edge: the window's height,
    // and less than its width but most of it.
    ASSERT_EQ(one.height, kHeight);
    EXPECT_LT(one.width, kWidth);
    EXPECT_GE(one.width, kWidth / 2);
    ASSERT_EQ(three.width, one.width);
    ASSERT_EQ(three.height, kHeight);

    // PNG values in [0, 1] (sRGB codes / 255). Measured: ceiling 0.0 after one bounce, 0.178 after three.
    // Half the measured gap leaves room for other patch sizes and rasterizers, and still fails a viewer that
    // did not step (gap 0).
    const double ceiling_one = mean_brightness(one, kCeiling);
    const double ceiling_three = mean_brightness(three, kCeiling);
    EXPECT_LT(ceiling_one, 0.02);
    EXPECT_GT(ceiling_three, ceiling_one + 0.08);
    // The lamp's own light (emission) is shown the same after any number of bounces (and is not black, as it
    // would be in a view of the newest bounce alone).
    EXPECT_GT(mean_brightness(one, kLamp), 0.9);
    EXPECT_DOUBLE_EQ(mean_brightness(one, kLamp), mean_brightness(three, kLamp));
}

// Auto exposure, the default: a closed furnace of uniform radiance L = 2 Le = 500, far beyond white at
// exposure 0, shows 0.18 grey (sRGB code 118) where the cube's far walls fill the view; --exposure 0 shows
// it white.
TEST(ViewerWindow, AutoExposureShowsABrightFurnaceAsMiddleGrey) {
    const std::string xvfb_run = test::find_in_path("xvfb-run");
    ASSERT_FALSE(xvfb_run.empty()) << "xvfb-run not found: scripts/install-deps.sh installs xvfb";
    const test::TempDir folder;
    folder.write("furnace.mtl", "newmtl glow\nKd 0.5 0.5 0.5\nKe 250 250 250\n");
    const std::string scene = folder.write(
        "furnace.obj", std::string("mtllib furnace.mtl\nusemtl glow\n") + test::kInwardUnitCubeCorners +
                           test::kInwardUnitCubeFirstFace + test::kInwardUnitCubeOtherFaces);
    auto shot = [&](const std::string& name, std::vector<std::string> more) {
        const std::string path = (folder.path() / name).string();
        std::vector<std::string> args{"-a",
                                      "-s",
                                      "-screen 0 1024x768x24",
                                      RAD_BINARY,
                                      "view",
                                      scene,
                                      "--patch-size",
                                      "0.5",
                                      "--width",
                                      std::to_string(kWidth),
                                      "--height",
                                      std::to_string(kHeight),
                                      "--steps",
                                      "40",
                                      "--screenshot",
                                      path,
                                      "--exit"};
        args.insert(args.end(), more.begin(), more.end());
        const test::CommandResult result = test::run_program(xvfb_run, args);
        EXPECT_EQ(result.status, 0) << result.err;
        return std::filesystem::exists(path) ? read_image(path) : Image{};
    };
    // The middle of the window: the walls seen from the default camera, which frames the cube from outside.
    constexpr Region kMiddle{0.40, 0.60, 0.40, 0.60};
    const Image automatic = shot("auto.png", {});
    ASSERT_EQ(automatic.height, kHeight);
    EXPECT_NEAR(mean_brightness(automatic, kMiddle), 118.0 / 255.0, 2.0 / 255.0);
    const Image fixed = shot("fixed.png", {"--exposure", "0"});
    ASSERT_EQ(fixed.height, kHeight);
    EXPECT_GT(mean_brightness(fixed, kMiddle), 0.99);
}

// An idle window sleeps until an event. Under Xvfb the window has the focus (no window manager: GLFW gives
// it input focus when it opens), where the loop used to draw without end: 1.8 cores measured (540 CPU ticks
// in 3 s, the render thread and llvmpipe's). Asleep it drew no frame in 3 s and used 0.6 % of a core; the
// bounds leave room for a stray expose event and a loaded machine, and fail a window that keeps drawing.
TEST(ViewerWindow, AnIdleWindowDrawsNothingAndSleeps) {
    const std::string xvfb_run = test::find_in_path("xvfb-run");
    ASSERT_FALSE(xvfb_run.empty()) << "xvfb-run not found: scripts/install-deps.sh installs xvfb";
    const test::CommandResult result = test::run_program(
        xvfb_run, {"-a", "-s", "-screen 0 1024x768x24", RAD_BINARY, "view", "builtin:cornell", "--patch-size",
                   "70", "--width", std::to_string(kWidth), "--height", std::to_string(kHeight), "--steps",
                   "2", "--idle", "3", "--exit"});
    ASSERT_EQ(result.status, 0) << result.err;
    std::size_t frames = 0;
    double cpu = 0.0;
    double share = 0.0;
    const std::size_t at = result.out.find("idle ");
    ASSERT_NE(at, std::string::npos) << result.out;
    ASSERT_EQ(std::sscanf(result.out.c_str() + at, "idle %*f s: %zu frames drawn, %lf s of CPU (%lf", &frames,
                          &cpu, &share),
              3)
        << result.out;
    EXPECT_LE(frames, 3u) << result.out;
    EXPECT_LT(share, 10.0) << result.out;
}

}  // namespace
}  // namespace rad
