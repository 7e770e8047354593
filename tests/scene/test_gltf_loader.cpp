// The glTF loader: what it makes of good files (transforms, .glb, embedded and external buffers, materials,
// textures as their mean, lights, the camera), and a one-line error naming file and element for bad ones.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "expect_input_error.hpp"
#include "rad/io/image_file.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"
#include "rad/util/srgb.hpp"
#include "scene/face_texcoords.hpp"
#include "test_support.hpp"

// The shared library exports it; tiny_gltf.h declares it only in its implementation part.
namespace tinygltf {
std::string base64_encode(unsigned char const* bytes, unsigned int length);
}

namespace rad {
namespace {

using json = nlohmann::json;
using test::TempDir;

std::string bytes_of(const std::vector<float>& floats) {
    std::string bytes(floats.size() * sizeof(float), '\0');
    std::memcpy(bytes.data(), floats.data(), bytes.size());
    return bytes;
}

std::string data_uri(const std::string& bytes) {
    return "data:application/octet-stream;base64," +
           tinygltf::base64_encode(reinterpret_cast<const unsigned char*>(bytes.data()),
                                   static_cast<unsigned int>(bytes.size()));
}

// One triangle in the z = 0 plane, counter-clockwise from +z (area 1/2), indexed (16-bit), on node 0, its
// buffer embedded: bytes 0-35 positions, 36-41 indices.
json triangle(const std::vector<float>& positions = {0, 0, 0, 1, 0, 0, 0, 1, 0}) {
    std::string blob = bytes_of(positions);
    const std::uint16_t index[3] = {0, 1, 2};
    blob.append(reinterpret_cast<const char*>(index), sizeof index);
    return json{
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"name", "n"}, {"mesh", 0}}}},
        {"meshes",
         {{{"name", "tri"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", positions.size() / 3}, {"type", "VEC3"}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positions.size() * 4}},
          {{"buffer", 0}, {"byteOffset", positions.size() * 4}, {"byteLength", 6}}}},
        {"buffers", {{{"byteLength", blob.size()}, {"uri", data_uri(blob)}}}},
    };
}

std::string write_gltf(const TempDir& dir, const json& doc, const std::string& name = "s.gltf") {
    return dir.write(name, doc.dump());
}

const Surface* find_surface(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces)
        if (s.name == name) return &s;
    return nullptr;
}

std::vector<glm::dvec3> points_of(const Surface& surface) {
    std::vector<glm::dvec3> points;
    for (auto v : surface.mesh.vertices()) points.push_back(to_glm(surface.mesh.point(v)));
    return points;
}

bool has_warning(const Scene& scene, const std::string& part) {
    for (const std::string& w : scene.warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], tolerance) << "channel " << c;
}

TEST(GltfLoader, NodeTransformsPlaceTheTriangle) {
    TempDir dir;
    json doc = triangle();
    // A parent that moves by (10, 0, 0) and a child that scales by 2 and turns 90° about z.
    doc["nodes"] = {
        {{"translation", {10, 0, 0}}, {"children", {1}}},
        {{"mesh", 0}, {"scale", {2, 2, 2}}, {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}}};
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].name, "tri");
    EXPECT_NEAR(surface_area(scene.surfaces[0].mesh), 2.0, 1e-12);
    const auto points = points_of(scene.surfaces[0]);
    ASSERT_EQ(points.size(), 3u);
    expect_near(points[0], {10, 0, 0});
    expect_near(points[1], {10, 2, 0});
    expect_near(points[2], {8, 0, 0});
    EXPECT_FALSE(scene.camera.has_value());
}

TEST(GltfLoader, AMatrixIsColumnMajorAndNoIndicesMeansInOrder) {
    TempDir dir;
    json doc = triangle();
    doc["meshes"][0]["primitives"][0].erase("indices");
    doc["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    expect_near(points_of(scene.surfaces[0])[1], {6, 6, 7});
}

TEST(GltfLoader, ExternalBufferAndBinaryGlbLoad) {
    TempDir dir;
    json doc = triangle();
    std::string blob = bytes_of({0, 0, 0, 1, 0, 0, 0, 1, 0});
    blob.append("\0\0\1\0\2\0", 6);
    dir.write("tri.bin", blob);
    doc["buffers"][0]["uri"] = "tri.bin";
    const std::string gltf = write_gltf(dir, doc);
    EXPECT_NEAR(total_area(load_scene(gltf)), 0.5, 1e-12);

    // The same model as .glb, written by tinygltf.
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string err, warn;
    ASSERT_TRUE(io.LoadASCIIFromFile(&model, &err, &warn, gltf)) << err;
    const std::string glb = (dir.path() / "tri.glb").string();
    ASSERT_TRUE(io.WriteGltfSceneToFile(&model, glb, true, true, false, true));
    const Scene scene = load_scene(glb);
    EXPECT_NEAR(total_area(scene), 0.5, 1e-12);
    EXPECT_EQ(scene.surfaces[0].name, "tri");
}

TEST(GltfLoader, MaterialsGiveReflectanceEmissionAndSides) {
    TempDir dir;
    json doc = triangle();
    doc["materials"] = {{{"name", "glow"},
                         {"doubleSided", true},
                         {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.4, 0.3, 1.0}}}},
                         {"emissiveFactor", {1.0, 0.5, 0.25}},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 8.0}}}}}}};
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_EQ(scene.surfaces.size(), 2u);
    const Surface* front = find_surface(scene, "tri");
    const Surface* back = find_surface(scene, "tri (back)");
    ASSERT_TRUE(front && back);
    EXPECT_TRUE(front->material.two_sided);
    expect_near(front->material.reflectance, {0.5, 0.4, 0.3});
    expect_near(front->material.emission, {8.0, 4.0, 2.0});
    EXPECT_TRUE(has_emitter(scene));
}

TEST(GltfLoader, WhiteIsClampedAndNoMaterialIsTheDefault) {
    TempDir dir;
    json doc = triangle();
    const Scene plain = load_scene(write_gltf(dir, doc));
    expect_near(plain.surfaces[0].material.reflectance, default_material().reflectance);
    EXPECT_TRUE(has_warning(plain, "without a material")) << plain.warnings.size();

    doc["materials"] = {{{"name", "white"}}};  // baseColorFactor defaults to 1
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene white = load_scene(write_gltf(dir, doc));
    expect_near(white.surfaces[0].material.reflectance, glm::dvec3(kMaxReflectance));
    EXPECT_TRUE(has_warning(white, "white"));
}

double linear_of(float value) {
    const double v = srgb_byte(value) / 255.0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

TEST(GltfLoader, ATextureCountsAsItsMeanInLinearSpace) {
    TempDir dir;
    const Image texture{
        2, 2, {{0.1f, 0.2f, 0.3f}, {0.9f, 0.8f, 0.7f}, {0.5f, 0.0f, 1.0f}, {0.25f, 0.5f, 0.75f}}};
    write_image((dir.path() / "tex.png").string(), texture);
    json doc = triangle();
    doc["materials"] = {
        {{"name", "tex"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}}};
    doc["textures"] = {{{"source", 0}}};
    doc["images"] = {{{"uri", "tex.png"}}};
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene scene = load_scene(write_gltf(dir, doc));
    glm::dvec3 mean(0.0);
    for (const glm::vec3& p : texture.pixels)
        for (int c = 0; c < 3; ++c) mean[c] += linear_of(p[c]) / 4.0;
    expect_near(scene.surfaces[0].material.reflectance, 0.5 * mean, 1e-12);
    EXPECT_FALSE(has_warning(scene, "images[0]"));

    // An image that does not decode: the factor alone, with a warning.
    dir.write("tex.png", "not a png");
    const Scene broken = load_scene(write_gltf(dir, doc));
    expect_near(broken.surfaces[0].material.reflectance, glm::dvec3(0.5));
    EXPECT_TRUE(has_warning(broken, "images[0]: not used")) << broken.warnings.size();
}

// TEXCOORD_0 goes with the base colour texture to the surface's faces, as glTF writes it (v = 0 at the
// image's top, no flip); a textured primitive without it, or with a count that differs, is a warning or an
// error naming the accessor.
TEST(GltfLoader, TextureCoordinatesFollowTheBaseColourTexture) {
    TempDir dir;
    write_image((dir.path() / "tex.png").string(), filled_image(2, 2, glm::vec3(0.5f)));
    json doc = triangle();
    doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    doc["textures"] = {{{"source", 0}}};
    doc["images"] = {{{"uri", "tex.png"}}};
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene untextured = load_scene(write_gltf(dir, doc));
    EXPECT_TRUE(has_warning(untextured, "1 textured primitive(s) have no texture coordinates"));
    EXPECT_FALSE(is_textured(untextured.surfaces[0]));

    const std::string uv = bytes_of({0.1f, 0.2f, 0.9f, 0.2f, 0.1f, 0.8f});
    doc["buffers"].push_back({{"byteLength", uv.size()}, {"uri", data_uri(uv)}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", uv.size()}});
    doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
    doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_TRUE(is_textured(scene.surfaces[0]));
    const glm::dvec2 at_x = texcoord_at(scene.surfaces[0].mesh, SurfaceMesh::FaceHandle(0), {1, 0, 0});
    EXPECT_NEAR(at_x.x, 0.9, 1e-6);
    EXPECT_NEAR(at_x.y, 0.2, 1e-6);
    const glm::dvec2 inside = texcoord_at(scene.surfaces[0].mesh, SurfaceMesh::FaceHandle(0), {0.25, 0.5, 0});
    EXPECT_NEAR(inside.x, 0.1 + 0.25 * 0.8, 1e-6);
    EXPECT_NEAR(inside.y, 0.2 + 0.5 * 0.6, 1e-6);

    doc["accessors"][2]["count"] = 2;
    test::expect_input_error([](const std::string& path) { load_scene(path); }, write_gltf(dir, doc),
                             {"s.gltf", "accessors[2]: 2 texture coordinates for 3 positions"});
}

// An image stored in a buffer view (as a .glb holds its images) is decoded after the view is checked.
TEST(GltfLoader, AnImageInABufferViewIsDecodedAfterItsViewIsChecked) {
    TempDir dir;
    const std::string png = (dir.path() / "grey.png").string();
    write_image(png, filled_image(2, 2, glm::vec3(0.5f)));
    std::ifstream in(png, std::ios::binary);
    const std::string image{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::string blob = bytes_of({0, 0, 0, 1, 0, 0, 0, 1, 0});
    blob.append("\0\0\1\0\2\0", 6);
    const std::size_t offset = blob.size();
    blob += image;
    json doc = triangle();
    doc["buffers"][0] = {{"byteLength", blob.size()}, {"uri", data_uri(blob)}};
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", image.size()}});
    doc["images"] = {{{"bufferView", 2}, {"mimeType", "image/png"}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"] = {{{"name", "grey"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene scene = load_scene(write_gltf(dir, doc));
    expect_near(scene.surfaces[0].material.reflectance, glm::dvec3(linear_of(0.5f)), 1e-12);

    doc["bufferViews"][2]["byteLength"] = image.size() + 1;
    test::expect_input_error(load_gltf, write_gltf(dir, doc),
                             {"s.gltf: bufferViews[2]: bytes", "exceed buffer 0"});
}

// Σ π Le A over the light's sphere.
glm::dvec3 emitted_power(const Scene& scene) {
    glm::dvec3 power(0.0);
    for (const Surface& s : scene.surfaces)
        power += std::numbers::pi * s.material.emission * surface_area(s.mesh);
    return power;
}

TEST(GltfLoader, APointLightEmitsItsPower) {
    TempDir dir;
    json doc = triangle();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "bulb"}, {"type", "point"}, {"intensity", 10.0}, {"color", {1.0, 0.5, 0.25}}},
        {{"name", "sun"}, {"type", "directional"}}};
    doc["nodes"] = {
        {{"mesh", 0}},
        {{"translation", {0.2, 0.2, 1.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
        {{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}};
    doc["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene scene = load_scene(write_gltf(dir, doc));
    const Surface* bulb = find_surface(scene, "bulb");
    ASSERT_NE(bulb, nullptr);
    EXPECT_EQ(bulb->mesh.n_faces(), 80u);
    const glm::dvec3 expected = 4.0 * std::numbers::pi * 10.0 * glm::dvec3(1.0, 0.5, 0.25);
    const glm::dvec3 power = emitted_power(scene);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[c], expected[c], 1e-9 * expected[c]) << c;
    EXPECT_TRUE(scene.sun.present());  // the directional light, of intensity 1 by default

    doc["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "spot";
    doc["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"] = json::object();
    const Scene spot = load_scene(write_gltf(dir, doc));
    EXPECT_TRUE(has_warning(spot, "1 spot light(s)"));
    EXPECT_NEAR(emitted_power(spot).x, expected.x, 1e-9 * expected.x);
}

// A directional light shines along its node's -z: the sun lies toward +z, here turned by a quarter turn
// about x (the quaternion (sin 45°, 0, 0, cos 45°) takes +z to -y).
TEST(GltfLoader, TheFirstDirectionalLightIsTheSun) {
    TempDir dir;
    json doc = triangle();
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"name", "sun"}, {"type", "directional"}, {"intensity", 3.0}, {"color", {1.0, 0.5, 0.25}}},
        {{"name", "moon"}, {"type", "directional"}}};
    const double h = std::sqrt(0.5);
    doc["nodes"] = {
        {{"mesh", 0}},
        {{"rotation", {h, 0.0, 0.0, h}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
        {{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}}};
    doc["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_TRUE(scene.sun.present());
    EXPECT_NEAR(scene.sun.direction.x, 0.0, 1e-12);
    EXPECT_NEAR(scene.sun.direction.y, -1.0, 1e-12);
    EXPECT_NEAR(scene.sun.direction.z, 0.0, 1e-12);
    EXPECT_EQ(scene.sun.irradiance, glm::dvec3(3.0, 1.5, 0.75));
    EXPECT_TRUE(has_warning(scene, "1 more directional light(s) left out"));
    EXPECT_FALSE(has_warning(scene, "no material emits light"));
}

TEST(GltfLoader, TheFirstPerspectiveCameraIsTheScenes) {
    TempDir dir;
    json doc = triangle();
    doc["cameras"] = {{{"type", "orthographic"},
                       {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
                      {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
    // Turned 90° about y: its −Z looks down −X.
    doc["nodes"] = {
        {{"mesh", 0}},
        {{"camera", 0}},
        {{"camera", 1}, {"translation", {1, 2, 3}}, {"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}}};
    doc["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_TRUE(scene.camera.has_value());
    expect_near(scene.camera->eye, {1, 2, 3});
    expect_near(scene.camera->target, {0, 2, 3});
    expect_near(scene.camera->up, {0, 1, 0});
    EXPECT_NEAR(scene.camera->fov_degrees, 0.5 * 180.0 / std::numbers::pi, 1e-12);
    EXPECT_TRUE(has_warning(scene, "1 orthographic camera(s) ignored"));
}

TEST(GltfLoader, StripsBecomeTrianglesAndPointsAreSkipped) {
    TempDir dir;
    json doc = triangle({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    doc["meshes"][0]["primitives"][0].erase("indices");
    doc["meshes"][0]["primitives"][0]["mode"] = 5;  // a strip of two triangles: the unit square
    doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"mode", 0}});
    const Scene scene = load_scene(write_gltf(dir, doc));
    EXPECT_NEAR(total_area(scene), 1.0, 1e-12);
    EXPECT_TRUE(has_warning(scene, "skipped 1 primitive(s)"));
}

TEST(GltfLoader, CornersLeftOverFromATriangleListAreIgnoredWithAWarning) {
    TempDir dir;
    json doc = triangle({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    doc["meshes"][0]["primitives"][0].erase("indices");  // 4 vertices: one triangle and one corner over
    const Scene scene = load_scene(write_gltf(dir, doc));
    EXPECT_NEAR(total_area(scene), 0.5, 1e-12);
    EXPECT_TRUE(
        has_warning(scene, "1 triangle primitive(s) have a corner count that is not a multiple of 3"));
}

TEST(GltfLoader, TrianglePairsOfAPlanarQuadBecomeTheQuad) {
    TempDir dir;
    json doc = triangle({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 1});
    doc["meshes"][0]["primitives"][0].erase("indices");
    doc["meshes"][0]["primitives"][0]["mode"] = 6;  // the fan (0 1 2), (0 2 3), (0 3 4)
    const Scene scene = load_scene(write_gltf(dir, doc));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    // The unit square, kept as one quad; the third triangle leaves the plane and stays a triangle.
    std::vector<std::size_t> corners;
    for (auto f : scene.surfaces[0].mesh.faces()) corners.push_back(scene.surfaces[0].mesh.valence(f));
    EXPECT_EQ(corners, (std::vector<std::size_t>{4, 3}));
}

// Each malformed file is refused with one line that names the file and the element at fault.
TEST(GltfLoader, MalformedFilesAreRefusedNamingTheElement) {
    struct Case {
        const char* what;
        void (*damage)(json&);
        std::vector<std::string> parts;
    };
    const Case cases[] = {
        {"huge count",
         [](json& d) { d["accessors"][0]["count"] = 4294967295u; },
         {"accessors[0]: count 4294967295 at byte offset 0 exceeds buffer view 0 (36 bytes)"}},
        {"view past buffer",
         [](json& d) { d["bufferViews"][1]["byteLength"] = 1000; },
         {"bufferViews[1]: bytes 36 + 1000 exceed buffer 0 (42 bytes)"}},
        {"index out of range",
         [](json& d) { d["accessors"][0]["count"] = 2; },
         {"accessors[1]: index 2 (element 2) is out of range (2 vertices)"}},
        {"component type",
         [](json& d) { d["accessors"][0]["componentType"] = 5123; },
         {"accessors[0]: component type 5123"}},
        {"missing accessor",
         [](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9; },
         {"meshes[0].primitives[0]: accessor 9 does not exist"}},
        {"missing mesh", [](json& d) { d["nodes"][0]["mesh"] = 5; }, {"nodes[0]: mesh 5 does not exist"}},
        {"missing material",
         [](json& d) { d["meshes"][0]["primitives"][0]["material"] = 3; },
         {"meshes[0].primitives[0]: material 3 does not exist"}},
        {"cycle",
         [](json& d) {
             d["nodes"][0]["children"] = {1};
             d["nodes"][1] = {{"children", {0}}};
         },
         {"nodes[0]: reached twice through the node hierarchy"}},
        {"two parents",
         [](json& d) {
             d["nodes"][0]["children"] = {2};
             d["nodes"][1] = {{"children", {2}}};
             d["nodes"][2] = json::object();
         },
         {"nodes[2]: is a child of both nodes[0] and nodes[1]"}},
        {"short matrix",
         [](json& d) { d["nodes"][0]["matrix"] = std::vector<double>(15, 1.0); },
         {"nodes[0]: matrix has 15 numbers"}},
        {"overflowing transform",
         [](json& d) {
             d["nodes"][0]["children"] = {1};
             d["nodes"][0]["scale"] = {1e300, 1e300, 1e300};
             d["nodes"][1] = {{"scale", {1e300, 1e300, 1e300}}};
         },
         {"nodes[1]: its transform from the world is not finite"}},
        {"outside the folder",
         [](json& d) { d["buffers"][0]["uri"] = "../outside.bin"; },
         {"uri '../outside.bin' reaches outside the scene's folder"}},
        {"absolute uri", [](json& d) { d["buffers"][0]["uri"] = "/etc/passwd"; }, {"is an absolute path"}},
        {"missing buffer file", [](json& d) { d["buffers"][0]["uri"] = "none.bin"; }, {"none.bin"}},
        {"required extension",
         [](json& d) { d["extensionsRequired"] = {"KHR_draco_mesh_compression"}; },
         {"requires extension 'KHR_draco_mesh_compression'"}},
        {"negative emission",
         [](json& d) {
             d["materials"] = {{{"name", "m"}, {"emissiveFactor", {-1, 0, 0}}}};
             d["meshes"][0]["primitives"][0]["material"] = 0;
         },
         {"materials[0]", "emission"}},
        {"unknown light",
         [](json& d) {
             d["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 4}}}};
         },
         {"nodes[0]: light 4 does not exist"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        TempDir dir;
        json doc = triangle();
        c.damage(doc);
        const std::string path = write_gltf(dir, doc, "bad.gltf");
        try {
            load_scene(path);
            ADD_FAILURE() << "expected an InputError";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
            for (const std::string& part : c.parts) EXPECT_NE(what.find(part), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

TEST(GltfLoader, BrokenJsonAndBrokenGlbAreOneLine) {
    TempDir dir;
    test::expect_input_error(load_gltf, dir.write("a.gltf", "{\"asset\": "), {"a.gltf: "});
    test::expect_input_error(
        load_gltf, dir.write("b.glb", std::string("glTF\2\0\0\0\xff\xff\0\0", 12) + "xxxxxxxx"), {"b.glb: "});
    test::expect_input_error(load_scene, (dir.path() / "c.gltf").string(), {"c.gltf: no such file"});
}

}  // namespace
}  // namespace rad
