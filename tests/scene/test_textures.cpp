// Textures: images decoded for the display (reduced when large, their mean kept), sampled as OpenGL samples
// them; texture coordinates read from OBJ (v flipped to glTF's convention) and interpolated over faces; each
// patch's mean albedo under its texture.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <random>

#include "rad/io/image_file.hpp"
#include "rad/mesh/patch_albedo.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/srgb.hpp"
#include "scene/face_texcoords.hpp"
#include "scene/texture_image.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

const std::string kTexturedFloor = std::string(RAD_SOURCE_DIR) + "/assets/hard/textured_floor.obj";

const Surface& surface_named(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces)
        if (s.name == name) return s;
    throw std::runtime_error("no surface " + name);
}

std::shared_ptr<const Texture> decode_png_file(const std::string& path) {
    const std::string bytes = test::read_file_text(path);
    std::string why;
    auto texture =
        decode_texture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "t", why);
    EXPECT_TRUE(texture) << why;
    return texture;
}

TEST(Texture, SamplesTexelCentresExactlyAndRepeats) {
    const test::TempDir dir;
    // 2 × 2: top row red, green; bottom row blue, white (linear 0.25 each, written as PNG).
    Image image = filled_image(2, 2);
    image.at(0, 0) = {0.25f, 0, 0};
    image.at(1, 0) = {0, 0.25f, 0};
    image.at(0, 1) = {0, 0, 0.25f};
    image.at(1, 1) = glm::vec3(0.25f);
    const std::string path = (dir.path() / "t.png").string();
    write_image(path, image);
    const auto texture = decode_png_file(path);
    ASSERT_TRUE(texture);
    EXPECT_EQ(texture->width, 2);
    const double q = srgb_byte_to_linear(srgb_byte(0.25f));
    EXPECT_NEAR(texture->linear_at({0.25, 0.25}).r, q, 1e-12);  // top left texel's centre: v = 0 is the top
    EXPECT_NEAR(texture->linear_at({0.75, 0.25}).g, q, 1e-12);
    EXPECT_NEAR(texture->linear_at({0.25, 0.75}).b, q, 1e-12);
    EXPECT_NEAR(texture->linear_at({1.25, -0.25}).b, q, 1e-12);  // repeated: (0.25, 0.75)
    // Halfway between the top two centres: the mean of red and green.
    const glm::dvec3 mid = texture->linear_at({0.5, 0.25});
    EXPECT_NEAR(mid.r, q / 2, 1e-12);
    EXPECT_NEAR(mid.g, q / 2, 1e-12);
    EXPECT_NEAR(texture->mean.r, q / 2, 1e-12);
    EXPECT_NEAR(texture->mean.b, q / 2, 1e-12);
}

TEST(Texture, ALargeImageIsReducedForTheDisplayKeepingItsMean) {
    const test::TempDir dir;
    // 4100 wide: reduced by 3 to 1366 texels (the last 2 columns dropped); the mean is the full image's.
    Image image = filled_image(4100, 2);
    for (int x = 0; x < image.width; ++x) {
        for (int y = 0; y < 2; ++y) image.at(x, y) = glm::vec3(x % 3 == 0 ? 1.0f : 0.0f);
    }
    const std::string path = (dir.path() / "wide.png").string();
    write_image(path, image);
    const auto texture = decode_png_file(path);
    ASSERT_TRUE(texture);
    EXPECT_EQ(texture->width, 1366);
    EXPECT_EQ(texture->height, 1);
    EXPECT_LE(texture->width, kMaxDisplayTextureSide);
    EXPECT_NEAR(texture->mean.r, 1367.0 / 4100.0, 1e-9);
    // Each reduced texel averages one white and two black columns in linear space: 1/3.
    EXPECT_NEAR(texture->linear_at({0.5, 0.5}).g, 1.0 / 3.0, 0.005);
}

// A PNG of 2 × 2 texels whose second chunk claims 2 GB (found by fuzz_gltf: stb_image allocated what the
// length claimed), and bytes of no image format: refused with a reason, nothing allocated for them.
TEST(Texture, AChunkLongerThanTheFileAndOtherFormatsAreRefused) {
    const std::string good =
        test::read_file_text(std::string(RAD_SOURCE_DIR) + "/assets/hard/half_white.png");
    std::string forged = good;
    // The chunk after IHDR (8 bytes of signature, 25 of IHDR) starts at byte 33: its length, big-endian.
    forged[33] = '\x7a';
    forged[34] = forged[35] = forged[36] = '\x00';
    std::string why;
    EXPECT_FALSE(
        decode_texture(reinterpret_cast<const unsigned char*>(forged.data()), forged.size(), "t", why));
    EXPECT_NE(why.find("a PNG chunk at byte 33 claims 2046820352 bytes, more than the file holds"),
              std::string::npos)
        << why;
    const std::string bmp = "BM" + std::string(60, '\0');
    EXPECT_FALSE(decode_texture(reinterpret_cast<const unsigned char*>(bmp.data()), bmp.size(), "t", why));
    EXPECT_EQ(why, "it is not a PNG or JPEG image");
    EXPECT_TRUE(decode_texture(reinterpret_cast<const unsigned char*>(good.data()), good.size(), "t", why))
        << why;
}

TEST(FaceTexcoords, MeanValueCoordinatesReproduceAnAffineMapOnAnyConvexFace) {
    SurfaceMesh mesh;
    mesh.request_halfedge_texcoords2D();
    // A convex pentagon in the plane x + y + z = 1, texture coordinates an affine function of position.
    const std::vector<glm::dvec3> corners = {
        {1, 0, 0}, {0.6, 0.6, -0.2}, {0, 1, 0}, {-0.4, 0.8, 0.6}, {0.2, -0.1, 0.9}};
    const auto uv_of = [](const glm::dvec3& p) { return glm::dvec2(0.3 + 2 * p.x - p.y, 0.1 * p.z + p.y); };
    std::vector<SurfaceMesh::VertexHandle> handles;
    for (const auto& c : corners) handles.push_back(mesh.add_vertex({c.x, c.y, c.z}));
    const auto face = mesh.add_face(handles);
    for (auto h : mesh.fh_range(face)) {
        const glm::dvec2 uv = uv_of(to_glm(mesh.point(mesh.to_vertex_handle(h))));
        mesh.set_texcoord2D(h, {static_cast<float>(uv.x), static_cast<float>(uv.y)});
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 200; ++k) {
        // A random convex combination of three corners lies inside.
        double w[3] = {unit(random), unit(random), unit(random)};
        const double sum = w[0] + w[1] + w[2];
        const glm::dvec3 p = (w[0] * corners[0] + w[1] * corners[2] + w[2] * corners[3 + k % 2]) / sum;
        const glm::dvec2 uv = texcoord_at(mesh, face, p);
        EXPECT_NEAR(uv.x, uv_of(p).x, 1e-6);
        EXPECT_NEAR(uv.y, uv_of(p).y, 1e-6);
    }
    // Corners and edges (where the coordinates' angles reach π) are exact too.
    EXPECT_NEAR(texcoord_at(mesh, face, corners[1]).x, uv_of(corners[1]).x, 1e-6);
    const glm::dvec3 on_edge = 0.3 * corners[3] + 0.7 * corners[4];
    EXPECT_NEAR(texcoord_at(mesh, face, on_edge).y, uv_of(on_edge).y, 1e-6);
}

TEST(ObjTextures, TextureCoordinatesFollowTheFloorWithVFlipped) {
    const Scene scene = load_scene(kTexturedFloor);
    const Surface& floor = surface_named(scene, "floor");
    ASSERT_TRUE(is_textured(floor));
    EXPECT_EQ(floor.material.texture->width, 16);
    EXPECT_NEAR(floor.material.reflectance.x, 0.4, 1e-12);  // Kd 0.8 × the image's mean 0.5
    EXPECT_FALSE(is_textured(surface_named(scene, "walls")));
    const SurfaceMesh::FaceHandle face(0);
    // u = x; OBJ's v = 1 at z = 0 is the image's top row, v = 0 here.
    const glm::dvec2 at_origin = texcoord_at(floor.mesh, face, {0, 0, 0});
    EXPECT_NEAR(at_origin.x, 0.0, 1e-6);
    EXPECT_NEAR(at_origin.y, 0.0, 1e-6);
    const glm::dvec2 inside = texcoord_at(floor.mesh, face, {0.25, 0, 0.75});
    EXPECT_NEAR(inside.x, 0.25, 1e-6);
    EXPECT_NEAR(inside.y, 0.75, 1e-6);
}

TEST(PatchAlbedo, PatchesTakeTheirOwnPartOfTheTextureAndTheSurfaceItsMean) {
    const Scene scene = load_scene(kTexturedFloor);
    const PatchMesh patches = build_patches(scene, {.patch_size = 1.0 / 16});
    const std::vector<glm::dvec3> albedo = patch_albedo(scene, patches);
    ASSERT_EQ(albedo.size(), patches.size());
    double area = 0.0, reflected = 0.0;
    int white = 0, black = 0;
    for (std::size_t q = 0; q < patches.size(); ++q) {
        const Patch& p = patches.patches[q];
        if (scene.surfaces[p.surface].name != "floor") {
            EXPECT_EQ(albedo[q], scene.surfaces[p.surface].material.reflectance);
            continue;
        }
        area += p.area;
        reflected += p.area * albedo[q].x;
        // Away from the image's border and its middle (where bilinear filtering blends a texel's width),
        // the white half reflects Kd and the black half nothing.
        const double x = p.centroid.x;
        if (x > 0.07 && x < 0.43) {
            EXPECT_NEAR(albedo[q].x, 0.8, 1e-9);
            ++white;
        } else if (x > 0.57 && x < 0.93) {
            EXPECT_NEAR(albedo[q].x, 0.0, 1e-9);
            ++black;
        }
    }
    EXPECT_EQ(white, 96);
    EXPECT_EQ(black, 96);
    EXPECT_NEAR(reflected / area, 0.4, 1e-9);  // the material's reflectance
}

}  // namespace
}  // namespace rad
