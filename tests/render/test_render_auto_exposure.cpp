// render's default exposure is auto: a furnace of uniform radiance L shows 0.18 grey (sRGB code 118) whatever
// L is, the EV it chose is printed, and --exposure EV still fixes it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rad/display/auto_exposure.hpp"
#include "rad/io/image_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

// A closed cube, every face emitting E = π Le with reflectance 0.5: L = 2 Le everywhere inside.
std::string write_furnace(const test::TempDir& dir, const std::string& le) {
    dir.write("furnace.mtl", "newmtl glow\nKd 0.5 0.5 0.5\nKe " + le + " " + le + " " + le + "\n");
    return dir.write("furnace.obj",
                     "mtllib furnace.mtl\nusemtl glow\n"
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                     "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 4 3 7 8\nf 1 4 8 5\nf 2 6 7 3\n");
}

test::CommandResult render_furnace(const test::TempDir& dir, const std::string& le, const std::string& out,
                                   std::vector<std::string> more = {}) {
    std::vector<std::string> args{
        "render",   write_furnace(dir, le),  "--patch-size", "0.5", "--width", "32", "--height", "32",
        "--camera", "0.5,0.5,0.9,0.3,0.4,0", "--fov",        "100", "--out",   out};
    args.insert(args.end(), more.begin(), more.end());
    return test::run_radiosity(args);
}

// sRGB's code of the key, 0.18: 1.055 · 0.18^(1/2.4) − 0.055 = 0.4614, × 255 = 117.7.
constexpr float kKeyCode = 118.0f / 255.0f;

TEST(RenderAutoExposure, AFurnaceShowsTheKeyGreyAtAnyBrightness) {
    for (const std::string le : {"0.001", "0.3", "250"}) {
        SCOPED_TRACE(le);
        test::TempDir dir;
        const std::string out = (dir.path() / "f.png").string();
        const test::CommandResult result = render_furnace(dir, le, out);
        ASSERT_EQ(result.status, 0) << result.err;
        const double expected_ev = std::log2(kAutoExposureKey / (2.0 * std::stod(le)));
        char printed[64];
        std::snprintf(printed, sizeof printed, "exposure %+.2f EV auto", expected_ev);
        EXPECT_NE(result.out.find(printed), std::string::npos) << result.out;
        const Image png = read_image(out);
        for (const glm::vec3& p : png.pixels)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], kKeyCode, 1.5f / 255.0f);
    }
}

// A fixed EV is applied as given: L = 0.6 at −1 EV is 0.3, sRGB code 149.
TEST(RenderAutoExposure, AFixedExposureIsKept) {
    test::TempDir dir;
    const std::string out = (dir.path() / "f.png").string();
    const test::CommandResult result = render_furnace(dir, "0.3", out, {"--exposure", "-1"});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("exposure -1.00 EV)"), std::string::npos) << result.out;
    const Image png = read_image(out);
    for (const glm::vec3& p : png.pixels) ASSERT_NEAR(p.g, 149.0f / 255.0f, 1.5f / 255.0f);
}

}  // namespace
}  // namespace rad
