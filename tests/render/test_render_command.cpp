// `radiosity render`: the images it writes show what the solution says, where it should be, and match the
// reviewed golden image; --export writes the mesh it draws.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/common.hpp>
#include <nlohmann/json.hpp>
#include <numbers>

#include "export_readers.hpp"
#include "golden_image.hpp"
#include "rad/io/image_file.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

using test::run_radiosity;

glm::vec3 mean_over(const Image& image, int x0, int y0, int x1, int y1) {
    glm::dvec3 sum(0.0);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += glm::dvec3(image.at(x, y));
    return glm::vec3(sum / double((x1 - x0) * (y1 - y0)));
}

Image render(const std::vector<std::string>& args, const std::string& out) {
    std::vector<std::string> all{"render"};
    all.insert(all.end(), args.begin(), args.end());
    all.insert(all.end(), {"--out", out});
    const auto result = run_radiosity(all);
    EXPECT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("wrote " + out), std::string::npos) << result.out;
    return read_image(out);
}

TEST(RenderCommand, CornellBoxHasRedLeftGreenRightLightOnTop) {
    test::TempDir dir;
    const Image image = render({"builtin:cornell", "--patch-size", "70", "--width", "128", "--height", "128"},
                               (dir.path() / "cornell.pfm").string());
    ASSERT_EQ(image.width, 128);
    const glm::vec3 left = mean_over(image, 8, 48, 20, 80);
    const glm::vec3 right = mean_over(image, 108, 48, 120, 80);
    EXPECT_GT(left.r, 3 * left.g);    // the red wall
    EXPECT_GT(right.g, 2 * right.r);  // the green wall
    // The brightest pixel is the light: in the top fifth of the image, in its middle fifth across, and at
    // least as bright as the light's own radiance (Le = 17 12 4) in linear units.
    std::size_t brightest = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        if (image.pixels[i].r > image.pixels[brightest].r) brightest = i;
    }
    EXPECT_LT(brightest / 128, 128u / 5);
    EXPECT_GT(brightest % 128, 128u * 2 / 5);
    EXPECT_LT(brightest % 128, 128u * 3 / 5);
    EXPECT_GE(image.pixels[brightest].r, 17.0f);
    EXPECT_GE(image.pixels[brightest].b, 4.0f);
}

TEST(RenderCommand, CornellBoxMatchesTheGoldenImage) {
    test::TempDir dir;
    const std::string out = (dir.path() / "cornell.png").string();
    // At exposure 0: auto exposure has its own tests (test_render_auto_exposure.cpp).
    render({"builtin:cornell", "--patch-size", "70", "--width", "256", "--height", "256", "--exposure", "0"},
           out);
    const test::GoldenResult result = test::compare_with_golden("cornell_256", out);
    EXPECT_TRUE(result.passed) << result.message;
}

// The largest relative difference of any pixel's channel from the furnace's B / π = 2 / π.
float worst_furnace_error(const Image& image) {
    const float expected = static_cast<float>(2.0 / std::numbers::pi);
    float worst = 0.0f;
    for (const glm::vec3& p : image.pixels) {
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(p[c] - expected) / expected);
    }
    return worst;
}

TEST(RenderCommand, FurnaceShowsEOverOneMinusRhoOverPiEverywhere) {
    test::TempDir dir;
    const Image image = render({test::write_furnace(dir), "--patch-size", "0.25", "--width", "96", "--height",
                                "96", "--camera", "0.5,0.5,0.9,0.3,0.4,0", "--fov", "100"},
                               (dir.path() / "furnace.pfm").string());
    EXPECT_LT(worst_furnace_error(image), 0.005f);
}

// The same furnace clustered, drawn on patches of the uniform size that gather their own last bounce, and
// its vertices gathering too: every ray meets a face of B = 2, so both gathers are exact.
TEST(RenderCommand, ClusteredFurnaceAtItsDefaultsShowsEOverOneMinusRhoOverPi) {
    test::TempDir dir;
    const Image image = render({test::write_furnace(dir), "--subdivision", "clustered", "--width", "96",
                                "--height", "96", "--camera", "0.5,0.5,0.9,0.3,0.4,0", "--fov", "100"},
                               (dir.path() / "furnace.pfm").string());
    EXPECT_LT(worst_furnace_error(image), 0.005f);
}

// Every vertex gathering (`on`) over the clustered furnace.
TEST(RenderCommand, ClusteredFurnaceWithItsFinalGatherShowsEOverOneMinusRhoOverPi) {
    test::TempDir dir;
    const Image image =
        render({test::write_furnace(dir), "--subdivision", "clustered", "--final-gather", "on", "--width",
                "96", "--height", "96", "--camera", "0.5,0.5,0.9,0.3,0.4,0", "--fov", "100"},
               (dir.path() / "furnace.pfm").string());
    EXPECT_LT(worst_furnace_error(image), 0.005f);
}

// The furnace of uniform patches gathered near surfaces (`near`): the room's corners gather, with every ray
// meeting a face of B = 2, and stay exact.
TEST(RenderCommand, UniformFurnaceGatheredNearSurfacesShowsEOverOneMinusRhoOverPi) {
    test::TempDir dir;
    const Image image =
        render({test::write_furnace(dir), "--patch-size", "0.25", "--final-gather", "near", "--width", "96",
                "--height", "96", "--camera", "0.5,0.5,0.9,0.3,0.4,0", "--fov", "100"},
               (dir.path() / "furnace.pfm").string());
    EXPECT_LT(worst_furnace_error(image), 0.005f);
}

TEST(RenderCommand, FlatModeShowsThePatchsOwnRadiosityAtItsCentre) {
    test::TempDir dir;
    // builtin:parallel at one patch per square: look up at the upper square's front (it faces down).
    const std::string json_path = (dir.path() / "solution.json").string();
    ASSERT_EQ(run_radiosity({"solve", "builtin:parallel", "--patch-size", "1", "--json", json_path}).status,
              0);
    std::ifstream in(json_path);
    const nlohmann::json doc = nlohmann::json::parse(in);
    double upper_b = -1.0;
    for (const auto& patch : doc.at("patches")) {
        if (patch.at("surface") == "upper") upper_b = patch.at("radiosity").at(0).get<double>();
    }
    ASSERT_GT(upper_b, 0.0);
    const Image image = render({"builtin:parallel", "--patch-size", "1", "--flat", "--width", "33",
                                "--height", "33", "--camera", "0.5,0.2,0.5,0.5,1,0.5,0,0,1", "--fov", "60"},
                               (dir.path() / "flat.pfm").string());
    const glm::vec3 centre = image.at(16, 16);
    EXPECT_NEAR(centre.r, upper_b / std::numbers::pi, 1e-6 * upper_b);
    EXPECT_EQ(centre.r, centre.g);
}

// --export writes the mesh render draws: with --flat every patch has corners of its own showing its own
// radiance, so each triangle's three corners agree; the colours take render's --exposure.
TEST(RenderCommand, ExportsTheMeshItDraws) {
    test::TempDir dir;
    const std::string gltf = (dir.path() / "flat.gltf").string();
    const auto result = run_radiosity({"render", "builtin:cornell", "--patch-size", "100", "--flat",
                                       "--width", "16", "--height", "16", "--exposure", "-1", "--out",
                                       (dir.path() / "flat.png").string(), "--export", gltf});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("wrote " + gltf), std::string::npos) << result.out;
    const test::ExportedMesh mesh = test::read_gltf_export(gltf);
    ASSERT_GT(mesh.triangles.size(), 0u);
    for (const glm::uvec3& t : mesh.triangles) {
        ASSERT_EQ(mesh.radiance[t[0]], mesh.radiance[t[1]]);
        ASSERT_EQ(mesh.radiance[t[0]], mesh.radiance[t[2]]);
    }
    for (std::size_t v = 0; v < mesh.colours.size(); ++v) {
        ASSERT_EQ(mesh.colours[v], glm::clamp(mesh.radiance[v] * 0.5f, 0.0f, 1.0f)) << "vertex " << v;
    }
}

TEST(RenderCommand, BadOptionsExitWith2AndWriteNothing) {
    test::TempDir dir;
    const std::string out = (dir.path() / "x.png").string();
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"render", "--out", (dir.path() / "x.jpg").string()}, "--out"},
        {{"render", "--out", (dir.path() / "no" / "x.png").string()}, "--out"},
        {{"render", "--out", out, "--camera", "1,2,3"}, "--camera"},
        {{"render", "--out", out, "--camera", "1,2,3,4,5,x"}, "--camera"},
        {{"render", "--out", out, "--camera", "0,0,0,0,0,0"}, "--camera"},
        {{"render", "--out", out, "--width", "0"}, "--width"},
        {{"render", "--out", out, "--fov", "200"}, "--fov"},
        {{"render", "--out", out, "--export", (dir.path() / "x.obj").string()}, "--export"},
        {{"render", "--out", out, "--export", (dir.path() / "no" / "x.ply").string()}, "--export"},
        {{"render", "--out", out, "--exposure", "nan"}, "--exposure"},
        {{"render", "--out", out, "--final-gather", "maybe"}, "--final-gather"},
        {{"render"}, "--out"},
    };
    for (const auto& [args, option] : cases) {
        const auto result = run_radiosity(args);
        EXPECT_EQ(result.status, 2) << args.back();
        EXPECT_NE(result.err.find(option), std::string::npos) << result.err;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace rad
