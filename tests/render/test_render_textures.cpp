// Texel detail on screen: the renderer multiplies a textured range's per-vertex irradiance by the texture's
// albedo per pixel, and `render` of the textured floor shows what a floor of two materials shows.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "gl/headless_context.hpp"
#include "gl/offscreen_target.hpp"
#include "gl/renderer.hpp"
#include "rad/io/image_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

TEST(RenderTextures, APixelShowsEmissionPlusTexelAlbedoTimesTheVertexValue) {
    HeadlessContext context;
    Renderer renderer;
    OffscreenTarget target{64, 64};
    // A square covering the view, u across it; the texture is one white and one black texel.
    const std::vector<glm::vec3> square = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const std::vector<glm::vec2> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::vector<std::uint32_t> triangles = {0, 1, 2, 0, 2, 3};
    auto texture = std::make_shared<Texture>();
    texture->width = 2;
    texture->height = 1;
    texture->srgb = {255, 255, 255, 0, 0, 0};
    texture->mean = glm::dvec3(0.5);
    const DisplayMesh::TexturedRange range{0, 2, texture, glm::vec3(0.8f), glm::vec3(0.1f, 0.0f, 0.0f)};
    renderer.upload_geometry(square, triangles, {});
    renderer.upload_textures(uv, std::span(&range, 1));
    renderer.update_colours(std::vector<glm::vec3>(4, glm::vec3(0.5f)));
    target.bind();
    renderer.draw(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f), {});
    const auto pixels = target.read_pixels();
    // At the texel centres (u = 1/4 and 3/4) the filter takes one texel alone.
    const glm::vec3 white = pixels[32 * 64 + 16], black = pixels[32 * 64 + 48];
    EXPECT_NEAR(white.r, 0.1f + 0.8f * 0.5f, 0.01f);
    EXPECT_NEAR(white.g, 0.8f * 0.5f, 0.01f);
    EXPECT_NEAR(black.r, 0.1f, 0.01f);
    EXPECT_NEAR(black.g, 0.0f, 0.01f);
    // Geometry uploaded again without textures draws the vertex values themselves.
    renderer.upload_geometry(square, triangles, {});
    renderer.update_colours(std::vector<glm::vec3>(4, glm::vec3(0.5f)));
    target.bind();
    renderer.draw(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f), {});
    EXPECT_EQ(target.read_pixels()[32 * 64 + 48], glm::vec3(0.5f));
    SCOPED_TRACE(context.description());
}

Image render_from_above(const std::string& scene, const std::filesystem::path& out) {
    const auto result = test::run_radiosity({"render", scene, "--patch-size", "0.0625", "--width", "96",
                                             "--height", "96", "--camera", "0.5,0.98,0.5,0.5,0,0.5,0,0,-1",
                                             "--fov", "90", "--out", out.string()});
    EXPECT_EQ(result.status, 0) << result.err;
    return read_image(out.string());
}

TEST(RenderTextures, TheTexturedFloorLooksLikeAFloorOfTwoMaterials) {
    const test::TempDir dir;
    const std::string hard = std::string(RAD_SOURCE_DIR) + "/assets/hard/";
    // The split floor: the same room, the floor cut at x = 0.5 into Kd 0.8 and Kd 0 without a texture.
    std::string obj = test::read_file_text(hard + "textured_floor.obj");
    const std::string textured = "o floor\nusemtl floor\nf 1/4 4/1 3/2 2/3\n";
    obj.replace(obj.find(textured), textured.size(),
                "v 0.5 0 0\nv 0.5 0 1\nusemtl white\nf 1 4 14 13\nusemtl black\nf 13 14 3 2\n");
    dir.write("textured_floor.mtl", test::read_file_text(hard + "textured_floor.mtl") +
                                        "\nnewmtl white\nKd 0.8 0.8 0.8\nnewmtl black\nKd 0 0 0\n");
    const Image split = render_from_above(dir.write("split.obj", obj), dir.path() / "split.pfm");
    const Image texture = render_from_above(hard + "textured_floor.obj", dir.path() / "textured.pfm");
    ASSERT_EQ(split.pixel_count(), texture.pixel_count());
    // The camera looks straight down (x to the right, 90° across from 0.98 above): the floor fills pixels 24
    // to 72 each way, its white half on the left. Compare the middle of each half, away from the image's
    // border and middle where texels are filtered.
    double split_white = 0.0, texture_white = 0.0, texture_black = 0.0;
    for (int y = 28; y < 68; ++y) {
        for (int x = 28; x < 44; ++x) {
            split_white += split.at(x, y).g;
            texture_white += texture.at(x, y).g;
        }
        for (int x = 53; x < 68; ++x) texture_black = std::max(texture_black, double(texture.at(x, y).g));
    }
    EXPECT_GT(split_white, 0.0);
    EXPECT_NEAR(texture_white, split_white, 0.02 * split_white);
    EXPECT_EQ(texture_black, 0.0);
}

}  // namespace
}  // namespace rad
