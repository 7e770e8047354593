// Exports of the solved scene: PLY (OpenMesh) and glTF / GLB (tinygltf) read back with the same geometry and
// the same colours as the display mesh in memory; the colours mean what they say (the Cornell box's red wall
// is red, the furnace has L = E / (1 − ρ) / π everywhere); nothing non-finite and no partial or temporary
// file is ever written; and `radiosity solve --export` writes every file asked for, or nothing for a bad
// option.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <limits>
#include <memory>
#include <numbers>
#include <set>

#include "export_readers.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/io/scene_export.hpp"
#include "rad/util/error.hpp"
#include "rad/util/srgb.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

using test::ExportedMesh;
using test::run_radiosity;

struct Solved {
    std::unique_ptr<RadiosityPipeline> pipeline;
    std::vector<glm::vec3> radiance;

    const DisplayMesh& display() const { return pipeline->display(); }
};

Solved solve(const PipelineOptions& options) {
    Solved solved{std::make_unique<RadiosityPipeline>(options), {}};
    solved.pipeline->solve();
    solved.radiance = solved.pipeline->vertex_radiance();
    return solved;
}

// The Cornell box at a coarse patch size: 100 mm, a few hundred patches.
const Solved& cornell() {
    static const Solved solved = [] {
        PipelineOptions options;
        options.scene.scene = "builtin:cornell";
        options.scene.patch_size = 100.0;
        return solve(options);
    }();
    return solved;
}

// A closed cube whose every face reflects ρ = 0.99 and emits E = 1: B = E / (1 − ρ) = 100 on every patch.
const Solved& furnace() {
    static const Solved solved = [] {
        PipelineOptions options;
        options.scene.scene = std::string(RAD_SOURCE_DIR) + "/assets/hard/furnace_rho_0_99.obj";
        options.scene.patch_size = 0.25;
        options.solver.method = "cg";
        options.solver.tolerance = 1e-7;
        return solve(options);
    }();
    return solved;
}

std::set<std::string> files_in(const std::filesystem::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        names.insert(entry.path().filename().string());
    }
    return names;
}

// Exposure −2 scales by exactly 1/4, so the expected values below are computed without rounding doubt.
constexpr double kExposure = -2.0;

glm::vec3 expected_colour(const glm::vec3& radiance) {
    return glm::clamp(radiance * 0.25f, glm::vec3(0.0f), glm::vec3(1.0f));
}

std::array<std::uint8_t, 3> expected_bytes(const glm::vec3& radiance) {
    const glm::vec3 shown = radiance * 0.25f;
    std::array<std::uint8_t, 3> bytes{};
    for (int c = 0; c < 3; ++c) {
        bytes[c] = static_cast<std::uint8_t>(std::lround(255.0f * srgb_encode(shown[c])));
    }
    return bytes;
}

// Corner k of exported triangle f is the display's corner k of triangle f: same position, normal and
// radiance, whether or not the writer gave the triangle vertices of its own.
void expect_same_corners(const ExportedMesh& exported, const DisplayMesh& display,
                         std::span<const glm::vec3> radiance) {
    ASSERT_EQ(exported.triangles.size(), display.triangles.size());
    for (std::size_t f = 0; f < display.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t e = exported.triangles[f][k];
            const std::uint32_t d = display.triangles[f][k];
            ASSERT_LT(e, exported.positions.size());
            ASSERT_EQ(exported.positions[e], display.positions[d]) << "triangle " << f << " corner " << k;
            ASSERT_EQ(exported.normals[e], display.normals[d]) << "triangle " << f << " corner " << k;
            ASSERT_EQ(exported.radiance[e], radiance[d]) << "triangle " << f << " corner " << k;
        }
    }
}

TEST(SceneExport, PlyRoundTripKeepsGeometryRadianceAndTheSrgbColoursOfAPng) {
    const Solved& solved = cornell();
    test::TempDir dir;
    const std::string path = (dir.path() / "cornell.ply").string();
    export_scene(path, solved.display(), solved.radiance, ExportOptions{.exposure = kExposure});
    const ExportedMesh exported = test::read_ply_export(path);

    // The display mesh of a uniform mesh is manifold: OpenMesh keeps every vertex, in order.
    ASSERT_EQ(exported.positions.size(), solved.display().vertex_count());
    EXPECT_EQ(exported.triangles, solved.display().triangles);
    expect_same_corners(exported, solved.display(), solved.radiance);
    std::size_t saturated = 0, unsaturated = 0;
    for (std::size_t v = 0; v < exported.positions.size(); ++v) {
        ASSERT_EQ(exported.colour_bytes[v], expected_bytes(solved.radiance[v])) << "vertex " << v;
        (exported.colour_bytes[v][0] == 255 ? saturated : unsaturated) += 1;
    }
    EXPECT_GT(saturated, 0u);    // the light
    EXPECT_GT(unsaturated, 0u);  // the walls
}

TEST(SceneExport, PlyKeepsTrianglesThatOpenMeshCannotJoin) {
    // Three triangles on one edge (0, 1): a non-manifold edge OpenMesh's half-edge mesh refuses.
    DisplayMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, -1, 0}};
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const std::vector<glm::vec3> radiance = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {0.5f, 0, 0}, {0, 0.5f, 0}};
    test::TempDir dir;
    const std::string path = (dir.path() / "fan.ply").string();
    export_scene(path, mesh, radiance);
    const ExportedMesh exported = test::read_ply_export(path);
    expect_same_corners(exported, mesh, radiance);
}

class GltfExport : public ::testing::TestWithParam<std::string> {};

TEST_P(GltfExport, RoundTripKeepsEveryValueAndDeclaresTheUnlitMaterial) {
    const Solved& solved = cornell();
    const DisplayMesh& display = solved.display();
    test::TempDir dir;
    const std::string path = (dir.path() / ("cornell" + GetParam())).string();
    export_scene(path, display, solved.radiance, ExportOptions{.exposure = kExposure});
    tinygltf::Model model;
    const ExportedMesh exported = test::read_gltf_export(path, &model);

    EXPECT_EQ(exported.positions, display.positions);
    EXPECT_EQ(exported.normals, display.normals);
    EXPECT_EQ(exported.triangles, display.triangles);
    EXPECT_EQ(exported.radiance, solved.radiance);
    ASSERT_EQ(exported.colours.size(), display.vertex_count());
    for (std::size_t v = 0; v < exported.colours.size(); ++v) {
        ASSERT_EQ(exported.colours[v], expected_colour(solved.radiance[v])) << "vertex " << v;
    }

    EXPECT_EQ(model.asset.version, "2.0");
    ASSERT_EQ(model.nodes.size(), 1u);
    EXPECT_EQ(model.nodes[0].mesh, 0);
    const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
    EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
    const tinygltf::Accessor& position = model.accessors[primitive.attributes.at("POSITION")];
    ASSERT_EQ(position.minValues.size(), 3u);
    ASSERT_EQ(position.maxValues.size(), 3u);
    for (int c = 0; c < 3; ++c) {
        float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
        for (const glm::vec3& p : display.positions) low = std::min(low, p[c]), high = std::max(high, p[c]);
        EXPECT_EQ(position.minValues[c], low);
        EXPECT_EQ(position.maxValues[c], high);
    }
    const auto& used = model.extensionsUsed;
    EXPECT_NE(std::find(used.begin(), used.end(), "KHR_materials_unlit"), used.end());
    ASSERT_EQ(primitive.material, 0);
    const tinygltf::Material& material = model.materials[0];
    EXPECT_EQ(material.extensions.count("KHR_materials_unlit"), 1u);
    EXPECT_EQ(material.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1.0, 1.0, 1.0, 1.0}));
}

INSTANTIATE_TEST_SUITE_P(Formats, GltfExport, ::testing::Values(".gltf", ".glb"),
                         [](const auto& info) { return info.param.substr(1); });

// A textured floor: the glTF keeps the texels (a primitive of its own with TEXCOORD_0 and the albedo as an
// embedded PNG, times COLOR_0, the irradiance / π its vertices carry); PLY, one colour per vertex, holds the
// radiance at each vertex (the texel under it times its irradiance). Both carry that radiance as floats.
TEST(SceneExport, ATexturedFloorKeepsItsTexelsInGltfAndItsVertexRadianceInPly) {
    PipelineOptions options;
    options.scene.scene = std::string(RAD_SOURCE_DIR) + "/assets/hard/textured_floor.obj";
    options.scene.patch_size = 0.125;
    const Solved solved = solve(options);
    const DisplayMesh& display = solved.display();
    ASSERT_EQ(display.textured.size(), 1u);
    const std::vector<glm::vec3> shown = vertex_shown_radiance(display, solved.radiance);
    const test::TempDir dir;
    for (const char* name : {"floor.glb", "floor.ply"}) {
        const std::filesystem::path path = dir.path() / name;
        export_scene(path, display, solved.radiance, {.exposure = kExposure});
        tinygltf::Model model;
        const ExportedMesh exported = path.extension() == ".glb"
                                          ? test::read_gltf_export(path.string(), &model)
                                          : test::read_ply_export(path.string());
        expect_same_corners(exported, display, shown);
        if (path.extension() != ".glb") continue;
        ASSERT_EQ(model.meshes[0].primitives.size(), 2u);  // the floor, then the rest
        const tinygltf::Primitive& floor = model.meshes[0].primitives[0];
        EXPECT_EQ(floor.attributes.count("TEXCOORD_0"), 1u);
        const tinygltf::Material& material = model.materials.at(static_cast<std::size_t>(floor.material));
        ASSERT_EQ(material.pbrMetallicRoughness.baseColorTexture.index, 0);
        ASSERT_EQ(model.images.size(), 1u);
        // tinygltf decoded the embedded PNG: the albedo, 0.8 on the white half (sRGB 231) and 0 on the
        // black one.
        const tinygltf::Image& image = model.images[0];
        ASSERT_EQ(image.width, 16);
        ASSERT_EQ(image.component, 4);
        EXPECT_EQ(image.image[(4 * 16 + 2) * 4], srgb_byte(0.8f));
        EXPECT_EQ(image.image[(4 * 16 + 12) * 4], 0);
        // A floor vertex's COLOR_0 is its irradiance / π at the exposure, which the albedo multiplies.
        const std::uint32_t v = display.triangles[display.textured[0].first_triangle][0];
        EXPECT_EQ(exported.colours[v], expected_colour(solved.radiance[v]));
    }
}

TEST(SceneExport, CornellRedWallIsRed) {
    const Solved& solved = cornell();
    const RadiosityPipeline& pipeline = *solved.pipeline;
    const DisplayMesh& display = solved.display();
    test::TempDir dir;
    const std::string path = (dir.path() / "cornell.ply").string();
    export_scene(path, display, solved.radiance);
    const ExportedMesh exported = test::read_ply_export(path);
    ASSERT_EQ(exported.triangles, display.triangles);

    std::size_t red_corners = 0;
    for (std::size_t f = 0; f < display.triangles.size(); ++f) {
        const std::uint32_t surface = pipeline.patches().patches[display.triangle_patch[f]].surface;
        if (pipeline.loaded().scene.surfaces[surface].name != "left wall") continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = exported.triangles[f][k];
            const auto& bytes = exported.colour_bytes[v];
            EXPECT_GT(bytes[0], bytes[1]) << "vertex " << v;
            EXPECT_GT(bytes[0], bytes[2]) << "vertex " << v;
            EXPECT_GT(exported.radiance[v].r, 3.0f * exported.radiance[v].g) << "vertex " << v;
            ++red_corners;
        }
    }
    EXPECT_GT(red_corners, 0u);
}

TEST(SceneExport, FurnaceExportsTheClosedFormRadianceAtEveryVertex) {
    const Solved& solved = furnace();
    test::TempDir dir;
    const std::string path = (dir.path() / "furnace.glb").string();
    // 2^−5 brings L ≈ 31.8 just below 1, so the colours are not clipped.
    export_scene(path, solved.display(), solved.radiance, ExportOptions{.exposure = -5.0});
    const ExportedMesh exported = test::read_gltf_export(path);
    const double expected = 1.0 / (1.0 - 0.99) / std::numbers::pi;  // E / (1 − ρ) / π
    ASSERT_EQ(exported.radiance.size(), solved.display().vertex_count());
    for (std::size_t v = 0; v < exported.radiance.size(); ++v) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(exported.radiance[v][c], expected, 1e-3 * expected) << "vertex " << v;
            ASSERT_EQ(exported.colours[v][c], exported.radiance[v][c] / 32.0f) << "vertex " << v;
        }
    }
}

TEST(SceneExport, RefusesWhatWouldMakeABadFileAndWritesNothing) {
    DisplayMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals.assign(3, glm::vec3(0, 0, 1));
    mesh.triangles = {{0, 1, 2}};
    const std::vector<glm::vec3> good(3, glm::vec3(0.5f));
    std::vector<glm::vec3> not_a_number = good;
    not_a_number[1].y = std::numeric_limits<float>::quiet_NaN();
    std::vector<glm::vec3> infinite = good;
    infinite[2].z = std::numeric_limits<float>::infinity();
    test::TempDir dir;
    for (const char* name : {"a.ply", "a.gltf", "a.glb"}) {
        const std::filesystem::path path = dir.path() / name;
        EXPECT_THROW(export_scene(path, mesh, not_a_number), std::invalid_argument) << name;
        EXPECT_THROW(export_scene(path, mesh, infinite), std::invalid_argument) << name;
        EXPECT_THROW(export_scene(path, mesh, good, ExportOptions{.exposure = 1000.0}),
                     std::invalid_argument);
        EXPECT_THROW(export_scene(path, mesh, std::span(good).first(2)), std::invalid_argument) << name;
        EXPECT_THROW(export_scene(path, DisplayMesh{}, {}), std::invalid_argument) << name;
    }
    EXPECT_THROW(export_scene(dir.path() / "a.obj", mesh, good), InputError);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
    // A folder that does not exist: the temporary cannot be made, and nothing is left anywhere.
    EXPECT_THROW(export_scene(dir.path() / "missing" / "a.ply", mesh, good), std::runtime_error);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(SceneExport, ReplacesAnOlderFileAndLeavesNoTemporary) {
    const Solved& solved = cornell();
    test::TempDir dir;
    const std::filesystem::path path = dir.write("cornell.glb", "an older file");
    export_scene(path, solved.display(), solved.radiance);
    EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"cornell.glb"}));
    EXPECT_EQ(test::read_gltf_export(path.string()).positions.size(), solved.display().vertex_count());
}

TEST(ExportCommand, SolveWritesEveryExportAndNothingElse) {
    test::TempDir dir;
    const std::string json = (dir.path() / "cornell.json").string();
    const std::string ply = (dir.path() / "a.ply").string();
    const std::string glb = (dir.path() / "b.glb").string();
    const auto result = run_radiosity({"solve", "builtin:cornell", "--patch-size", "100", "--json", json,
                                       "--export", ply, "--export", glb, "--exposure", "1"});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.out.find("wrote " + ply + "\n"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("wrote " + glb + "\n"), std::string::npos) << result.out;
    EXPECT_EQ(files_in(dir.path()), (std::set<std::string>{"cornell.json", "a.ply", "b.glb"}));

    // Both hold the same solution; the PLY's bytes are the sRGB of the GLB's colours, here at exposure +1.
    const ExportedMesh from_ply = test::read_ply_export(ply);
    const ExportedMesh from_glb = test::read_gltf_export(glb);
    ASSERT_EQ(from_ply.positions.size(), from_glb.positions.size());
    EXPECT_GT(from_glb.triangles.size(), 0u);
    EXPECT_EQ(from_ply.triangles, from_glb.triangles);
    EXPECT_EQ(from_ply.positions, from_glb.positions);
    EXPECT_EQ(from_ply.radiance, from_glb.radiance);
    for (std::size_t v = 0; v < from_glb.colours.size(); ++v) {
        ASSERT_EQ(from_glb.colours[v], glm::clamp(from_glb.radiance[v] * 2.0f, 0.0f, 1.0f)) << "vertex " << v;
        for (int c = 0; c < 3; ++c) ASSERT_EQ(from_ply.colour_bytes[v][c], srgb_byte(from_glb.colours[v][c]));
    }
}

TEST(ExportCommand, BadExportsExitTwoNamingTheOptionBeforeAnyWork) {
    test::TempDir dir;
    const std::string json = (dir.path() / "x.json").string();
    const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
        {{"--export", (dir.path() / "x.obj").string()},
         {"--export", "x.obj", "unknown export format '.obj'"}},
        {{"--export", (dir.path() / "x").string()}, {"--export", "no extension"}},
        {{"--export", (dir.path() / "a.ply").string(), "--export", (dir.path() / "nope" / "x.glb").string()},
         {"--export", "x.glb", "does not exist"}},
        {{"--exposure", "nan"}, {"--exposure"}},
        {{"--exposure", "1e9"}, {"--exposure"}},
    };
    for (const auto& [extra, parts] : cases) {
        std::vector<std::string> args = {"solve", "builtin:cornell", "--json", json};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto result = run_radiosity(args);
        EXPECT_EQ(result.status, 2) << parts[0] << ": " << result.err;
        for (const std::string& part : parts)
            EXPECT_NE(result.err.find(part), std::string::npos) << result.err;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_EQ(result.out.find("form factors"), std::string::npos) << "no work before the refusal";
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace rad
