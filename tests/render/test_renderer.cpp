// The OpenGL renderer on a headless context: what it draws is what it was given, at the right place.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "gl/renderer.hpp"
#include "rad/util/srgb.hpp"

namespace rad {
namespace {

// A unit square in z = 0 facing +z, seen head-on by an orthographic camera covering [-1, 1]².
const std::vector<glm::vec3> kSquare = {
    {-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}};
const std::vector<std::uint32_t> kTriangles = {0, 1, 2, 0, 2, 3};
const std::vector<std::uint32_t> kOutline = {0, 1, 1, 2, 2, 3, 3, 0};

glm::mat4 front_view() {
    return glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
}

class RendererTest : public ::testing::Test {
  protected:
    HeadlessContext context;
    Renderer renderer;
    OffscreenTarget target{64, 64};
};

TEST_F(RendererTest, FlatColourArrivesExactlyInTheLinearImage) {
    renderer.upload_geometry(kSquare, kTriangles, kOutline);
    const std::vector<glm::vec3> colour(4, glm::vec3(0.3f, 1234.5f, 1e-4f));
    renderer.update_colours(colour);
    target.bind();
    renderer.draw(front_view(), {});
    const auto pixels = target.read_pixels();
    EXPECT_EQ(pixels[32 * 64 + 32], colour[0]);      // centre: exactly the radiance given, float storage
    EXPECT_EQ(pixels[2 * 64 + 2], glm::vec3(0.0f));  // corner: background
    SCOPED_TRACE(context.description());
}

// The viewer's kind of framebuffer (8-bit sRGB, one sample): each pixel holds the sRGB code a PNG of the same
// radiance holds, to the one step by which drivers' rounding may differ, and radiance above 1 shows white.
TEST_F(RendererTest, DisplayFormatHoldsThePngsSrgbCodes) {
    OffscreenTarget display(64, 64, 1, PixelFormat::display_srgb8);
    renderer.upload_geometry(kSquare, kTriangles, kOutline);
    const glm::vec3 colour(0.2f, 0.5f, 2.0f);
    renderer.update_colours(std::vector<glm::vec3>(4, colour));
    display.bind();
    DrawOptions encoded;
    encoded.encode_srgb = true;
    renderer.draw(front_view(), encoded);
    const glm::vec3 shown = display.read_pixels()[32 * 64 + 32];
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(srgb_byte(shown[c]), srgb_byte(colour[c]), 1) << "channel " << c << ": " << shown[c];
    }
    EXPECT_FLOAT_EQ(shown.b, 1.0f);
    // The float target is unaffected by the display target's sRGB switch.
    target.bind();
    renderer.draw(front_view(), {});
    EXPECT_EQ(target.read_pixels()[32 * 64 + 32], colour);
}

// The false-colour view: a radiance of luminance 683 · Y cd/m² at 10^1.5 on a scale from 10^0 to 10^4 is
// three eighths up the map; the colours between the stops are interpolated alike in the shader and on the
// CPU (the legend's), and a luminance past either end takes the end's colour.
TEST_F(RendererTest, FalseColoursShowTheLuminanceOnTheLegendsScale) {
    renderer.upload_geometry(kSquare, kTriangles, kOutline);
    const double luminance = std::pow(10.0, 1.5);
    const float grey = static_cast<float>(luminance / kLuminousEfficacy);  // Y of a grey is its value
    DrawOptions options;
    options.false_colour = FalseColourScale{0.0, 4.0};
    const auto shown = [&](float radiance) {
        renderer.update_colours(std::vector<glm::vec3>(4, glm::vec3(radiance)));
        target.bind();
        renderer.draw(front_view(), options);
        return target.read_pixels()[32 * 64 + 32];
    };
    const auto expect_near = [](const glm::vec3& actual, const glm::vec3& expected, const char* what) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 1e-3f) << what << ", channel " << c;
    };
    expect_near(shown(grey), false_colour(1.5 / 4.0), "10^1.5");
    expect_near(shown(1e6f), false_colour_stops().back(), "above the scale");
    expect_near(shown(1e-9f), false_colour_stops().front(), "below the scale");
}

TEST_F(RendererTest, BackFacesAreNotDrawn) {
    const std::vector<std::uint32_t> reversed = {0, 2, 1, 0, 3, 2};
    renderer.upload_geometry(kSquare, reversed, {});
    renderer.update_colours(std::vector<glm::vec3>(4, glm::vec3(1.0f)));
    target.bind();
    renderer.draw(front_view(), {});
    EXPECT_EQ(target.read_pixels()[32 * 64 + 32], glm::vec3(0.0f));
}

TEST_F(RendererTest, ColoursInterpolateAndTopRowComesFirst) {
    renderer.upload_geometry(kSquare, kTriangles, {});
    // Bottom corners dark, top corners bright.
    renderer.update_colours(
        std::vector<glm::vec3>{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(1.0f), glm::vec3(1.0f)});
    target.bind();
    renderer.draw(front_view(), {});
    const auto pixels = target.read_pixels();
    // Rows 20 and 43 from the top have their centres at y = +0.359 and -0.359: linear interpolation from
    // 0 at y = -0.5 to 1 at y = +0.5 gives 0.859 and 0.141.
    const float upper = pixels[20 * 64 + 32].x;
    const float lower = pixels[43 * 64 + 32].x;
    EXPECT_NEAR(upper, 0.859f, 0.01f);
    EXPECT_NEAR(lower, 0.141f, 0.01f);
    EXPECT_EQ(renderer.geometry_uploads(), 1u);
    EXPECT_EQ(renderer.colour_uploads(), 1u);
}

TEST_F(RendererTest, OutlineDrawsThePatchEdges) {
    renderer.upload_geometry(kSquare, kTriangles, kOutline);
    renderer.update_colours(std::vector<glm::vec3>(4, glm::vec3(0.5f)));
    target.bind();
    DrawOptions options;
    options.outline = true;
    options.outline_colour = glm::vec3(0.0f, 0.0f, 7.0f);
    renderer.draw(front_view(), options);
    const auto pixels = target.read_pixels();
    // The left edge is at x = -0.5: pixel column 16. Some pixel of that column near the middle is the line.
    float blue = 0.0f;
    for (int x = 14; x <= 17; ++x) blue = std::max(blue, pixels[32 * 64 + x].z);
    EXPECT_GT(blue, 3.0f);
    EXPECT_EQ(pixels[32 * 64 + 32], glm::vec3(0.5f));
}

}  // namespace
}  // namespace rad
