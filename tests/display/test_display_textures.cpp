// Texel detail in the display mesh: textured vertices carry the irradiance their patches receive, so the
// albedo under a vertex times its value gives back the radiosity where the albedo is the patch's own.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "rad/display/display_mesh.hpp"
#include "rad/scene/scene_loader.hpp"
#include "solved_scene.hpp"

namespace rad {
namespace {

const std::string kTexturedFloor = std::string(RAD_SOURCE_DIR) + "/assets/hard/textured_floor.obj";

class TexturedDisplay : public ::testing::TestWithParam<ColourMode> {
  protected:
    void SetUp() override {
        solved = test::solve_scene(load_scene(kTexturedFloor), Subdivision::uniform, 1.0 / 16);
        display = build_display_mesh(*solved->system.patches, {.mode = GetParam()},
                                     {&solved->scene, solved->system.transport->reflectance});
    }
    std::unique_ptr<test::SolvedScene> solved;
    DisplayMesh display;
};

TEST_P(TexturedDisplay, TheFloorIsOneTexturedRangeAndTheRestIsNot) {
    ASSERT_EQ(display.textured.size(), 1u);
    const DisplayMesh::TexturedRange& range = display.textured[0];
    EXPECT_EQ(range.triangle_count, 2u * 256u);      // 16 × 16 quads
    EXPECT_NEAR(range.albedo_scale.x, 0.8f, 1e-6f);  // reflectance 0.4 over the image's mean 0.5: Kd
    EXPECT_EQ(display.texcoords.size(), display.vertex_count());
    for (std::uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t) {
        const std::uint32_t q = display.triangle_patch[t];
        EXPECT_EQ(solved->scene.surfaces[solved->system.patches->patches[q].surface].name, "floor");
    }
}

TEST_P(TexturedDisplay, TexelAlbedoTimesIrradianceIsTheRadiosityOnAPatchOfOneColour) {
    const std::vector<glm::vec3> values = vertex_radiance(display, solved->radiosity);
    const std::vector<glm::vec3> shown = vertex_shown_radiance(display, values);
    // The same mesh drawn without texturing: the floor has no texture seam, so its vertices are the same.
    const DisplayMesh plain = build_display_mesh(*solved->system.patches, {.mode = GetParam()});
    ASSERT_EQ(plain.vertex_count(), display.vertex_count());
    const std::vector<glm::vec3> plain_values = vertex_radiance(plain, solved->radiosity);
    const DisplayMesh::TexturedRange& range = display.textured[0];
    const PatchMesh& patches = *solved->system.patches;
    int white = 0, black = 0;
    for (std::uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t) {
        const std::uint32_t q = display.triangle_patch[t];
        const double x = patches.patches[q].centroid.x;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = display.triangles[t][k];
            if (x > 0.2 && x < 0.3) {
                // White half, two patches from any other albedo: the irradiance reconstructed at the vertex
                // times 0.8 is the radiosity reconstructed there (the reconstruction is linear).
                EXPECT_NEAR(shown[v].y, plain_values[v].y, 1e-5f * plain_values[v].y);
                if (GetParam() == ColourMode::flat) {
                    EXPECT_NEAR(shown[v].y, solved->radiosity[q].y / std::numbers::pi, 1e-5 * shown[v].y);
                }
                ++white;
            } else if (x > 0.57 && x < 0.93) {
                // Black half: nothing shown.
                EXPECT_EQ(shown[v].y, 0.0f);
                ++black;
            }
        }
    }
    EXPECT_GT(white, 0);
    EXPECT_GT(black, 0);
}

TEST_P(TexturedDisplay, WithoutTheSceneNothingIsTextured) {
    const DisplayMesh plain = build_display_mesh(*solved->system.patches, {.mode = GetParam()});
    EXPECT_TRUE(plain.textured.empty());
    EXPECT_TRUE(plain.texcoords.empty());
    EXPECT_TRUE(plain.light.patch_irradiance.empty());
}

INSTANTIATE_TEST_SUITE_P(Modes, TexturedDisplay, ::testing::Values(ColourMode::smooth, ColourMode::flat));

}  // namespace
}  // namespace rad
