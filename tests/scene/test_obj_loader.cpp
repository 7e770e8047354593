// The OBJ + MTL loader: what it makes of good files, and a one-line error naming file and line for bad ones.
#include <gtest/gtest.h>

#include <cmath>

#include "expect_input_error.hpp"
#include "rad/io/image_file.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"
#include "rad/util/srgb.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

using test::TempDir;

const Surface* find_surface(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

// tinyobjloader's number parser is not always correctly rounded: compare within a few ulps.
void expect_rgb(const glm::dvec3& actual, const glm::dvec3& expected) {
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(actual[c], expected[c]) << "channel " << c;
}

void expect_obj_error(const std::string& path, std::initializer_list<std::string> parts) {
    test::expect_input_error(load_obj, path, parts);
}

const char* kMtl =
    "newmtl white\nKd 0.7 0.7 0.7\n"
    "newmtl lamp\nKd 0.5 0.5 0.5\nKe 4 3 2\n";

// map_Kd: the transport sees the mean albedo, so Kd is multiplied by the texture's mean linear colour (the
// PNG holds sRGB bytes). A texture not found, or outside the scene's folder, leaves Kd, counted in a warning.
TEST(ObjLoader, AMapKdTextureCountsAsItsMeanInLinearSpace) {
    TempDir dir;
    const Image texture{
        2, 2, {{0.1f, 0.2f, 0.3f}, {0.9f, 0.8f, 0.7f}, {0.5f, 0.0f, 1.0f}, {0.25f, 0.5f, 0.75f}}};
    write_image((dir.path() / "tex.png").string(), texture);
    dir.write("s.mtl",
              "newmtl tex\nKd 0.5 0.5 0.5\nmap_Kd tex.png\n"
              "newmtl gone\nKd 0.25 0.25 0.25\nmap_Kd missing.png\n"
              "newmtl outside\nKd 0.75 0.75 0.75\nmap_Kd ../tex.png\n");
    const std::string obj = dir.write("s.obj",
                                      "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                      "o a\nusemtl tex\nf 1 2 3\no b\nusemtl gone\nf 1 3 4\n"
                                      "o c\nusemtl outside\nf 1 2 4\n");
    const Scene scene = load_obj(obj);
    glm::dvec3 mean(0.0);
    for (const glm::vec3& p : texture.pixels) {
        for (int c = 0; c < 3; ++c) {
            const double v = srgb_byte(p[c]) / 255.0;
            mean[c] += (v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4)) / 4.0;
        }
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(find_surface(scene, "a")->material.reflectance[c], 0.5 * mean[c], 1e-7);
    expect_rgb(find_surface(scene, "b")->material.reflectance, glm::dvec3(0.25));
    expect_rgb(find_surface(scene, "c")->material.reflectance, glm::dvec3(0.75));
    std::size_t texture_warnings = 0;
    for (const std::string& w : scene.warnings) {
        if (w.find("texture") == std::string::npos) continue;
        ++texture_warnings;
        EXPECT_NE(w.find("2 texture(s) (map_Kd) not read, first 'missing.png' (not found)"),
                  std::string::npos)
            << w;
    }
    EXPECT_EQ(texture_warnings, 1u);
}

TEST(ObjLoader, MaterialsAndGroupsBecomeSurfaces) {
    TempDir dir;
    dir.write("s.mtl", kMtl);
    const std::string obj = dir.write("s.obj",
                                      "mtllib s.mtl\n"
                                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                      "v 0 0 1\nv 1 0 1\nv 1 1 1\n"
                                      "o floor\nusemtl white\nf 1 2 3 4\n"
                                      "o lamp\nusemtl lamp\nf 5 7 6\n");
    const Scene scene = load_obj(obj);
    ASSERT_EQ(scene.surfaces.size(), 2u);
    const Surface* floor = find_surface(scene, "floor");
    const Surface* lamp = find_surface(scene, "lamp");
    ASSERT_TRUE(floor && lamp);
    expect_rgb(floor->material.reflectance, glm::dvec3(0.7));
    expect_rgb(lamp->material.emission, glm::dvec3(4, 3, 2));
    EXPECT_EQ(floor->mesh.n_faces(), 1u);
    EXPECT_DOUBLE_EQ(surface_area(floor->mesh), 1.0);
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(ObjLoader, UsemtlRunsInOneObjectAreSeparateSurfaces) {
    TempDir dir;
    dir.write("s.mtl", kMtl);
    const std::string obj = dir.write("s.obj",
                                      "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                      "o room\nusemtl white\nf 1 2 3\nusemtl lamp\nf 1 3 4\n");
    const Scene scene = load_obj(obj);
    ASSERT_EQ(scene.surfaces.size(), 2u);
    EXPECT_NE(find_surface(scene, "room/white"), nullptr);
    EXPECT_NE(find_surface(scene, "room/lamp"), nullptr);
}

TEST(ObjLoader, OnlyPolygonsThatAreNotPlanarConvexAreTriangulated) {
    TempDir dir;
    const std::string obj =
        dir.write("p.obj",
                  // a convex pentagon, an L-shaped hexagon, a non-planar quad
                  "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\n"
                  "v 0 0 5\nv 2 0 5\nv 2 1 5\nv 1 1 5\nv 1 2 5\nv 0 2 5\n"
                  "v 0 0 9\nv 1 0 9\nv 1 1 9.3\nv 0 1 9\n"
                  "g pentagon\nf 1 2 3 4 5\ng ell\nf 6 7 8 9 10 11\ng bent\nf 12 13 14 15\n");
    const Scene scene = load_obj(obj);
    EXPECT_EQ(find_surface(scene, "pentagon")->mesh.n_faces(), 1u);
    EXPECT_EQ(find_surface(scene, "ell")->mesh.n_faces(), 4u);
    EXPECT_NEAR(surface_area(find_surface(scene, "ell")->mesh), 3.0, 1e-12);
    EXPECT_EQ(find_surface(scene, "bent")->mesh.n_faces(), 2u);
}

TEST(ObjLoader, ZeroAreaFacesAreDroppedAndCounted) {
    TempDir dir;
    const std::string obj = dir.write("z.obj",
                                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 0 0\n"
                                      "f 1 2 3\nf 1 2 4\nf 1 1 2\n");
    const Scene scene = load_obj(obj);
    EXPECT_EQ(scene.surfaces.at(0).mesh.n_faces(), 1u);
    bool counted = false;
    for (const auto& w : scene.warnings) counted |= w.find("dropped 2 face") != std::string::npos;
    EXPECT_TRUE(counted);
}

TEST(ObjLoader, MissingMtlFallsBackToTheDefaultMaterial) {
    TempDir dir;
    const std::string obj =
        dir.write("m.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl white\nf 1 2 3\n");
    const Scene scene = load_obj(obj);
    expect_rgb(scene.surfaces.at(0).material.reflectance, glm::dvec3(0.5));
    EXPECT_EQ(scene.surfaces.at(0).material.emission, glm::dvec3(0.0));
    bool warned = false;
    for (const auto& w : scene.warnings)
        warned |= w.find("m.obj:1: material library 'gone.mtl' not found") == 0 ||
                  w.find("gone.mtl' not found") != std::string::npos;
    EXPECT_TRUE(warned);
}

// A name longer than the file system allows made std::filesystem throw (found by fuzz_obj: exit 1, not 2).
TEST(ObjLoader, MtlNameTooLongForTheFileSystemIsNotFound) {
    TempDir dir;
    const std::string name(300, 'm');
    const Scene scene =
        load_obj(dir.write("long.obj", "mtllib " + name + ".mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"));
    ASSERT_FALSE(scene.warnings.empty());
    // Messages show a long name cut short.
    EXPECT_NE(
        scene.warnings[0].find("long.obj:1: material library '" + name.substr(0, 40) + "...' not found"),
        std::string::npos)
        << scene.warnings[0];
}

TEST(ObjLoader, BadInputNamesFileAndLine) {
    TempDir dir;
    expect_obj_error((dir.path() / "absent.obj").string(), {"absent.obj", "no such file"});
    expect_obj_error(dir.write("a.obj", "v 0 0 0\nv 1 abc 0\n"), {"a.obj:2:", "malformed number 'abc'"});
    expect_obj_error(dir.write("b.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 9\n"),
                     {"b.obj:4:", "vertex index 9 is out of range"});
    expect_obj_error(dir.write("c.obj", "v 0 0 0\nv nan 0 0\n"), {"c.obj:2:", "not a finite number"});
    expect_obj_error(dir.write("d.obj", "v 0 0 0\nv 1 0 inf\n"), {"d.obj:2:", "not a finite number"});
    // A face of two corners is skipped; with nothing else, nothing is left.
    expect_obj_error(dir.write("e.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"), {"e.obj", "no faces"});
    expect_obj_error(dir.write("f.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n"), {"f.obj:4:", "index 0"});
    expect_obj_error(dir.write("g.obj", "v 0 0\n"), {"g.obj:1:", "needs 3 to 7 numbers"});
    expect_obj_error(dir.write("h.obj", std::string("v 0 0 0\n\x7f\x45\x4c\x46\0\0junk", 19)),
                     {"h.obj:2:", "binary"});
    expect_obj_error(dir.write("i.obj", "# nothing but a comment\n"), {"i.obj", "no faces"});
    expect_obj_error(dir.write("j.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2 3\n"),
                     {"j.obj:4:", "texture coordinate index 1 is out of range"});
    // tinyobjloader ends a line at a lone '\r' too (found by fuzz_obj: the face was read unchecked).
    expect_obj_error(dir.write("k.obj", "v 0 0 0\rv 1 0 0\r\nf 1 2 9\r"),
                     {"k.obj:3:", "vertex index 9 is out of range"});
    // tinyobjloader reads a face's corners past a '#' (found by fuzz_obj: corner 5 was read unchecked).
    expect_obj_error(dir.write("l.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3# 5\n"),
                     {"l.obj:4:", "malformed vertex index '3#'"});
    // Coordinates whose squared lengths overflow (found by fuzz_obj: an infinite area).
    expect_obj_error(dir.write("m.obj", "v 0 0 0\nv 2e30 0 0\nv 0 1 0\nf 1 2 3\n"),
                     {"m.obj:2:", "coordinate '2e30' is beyond ±1e30"});
    // tinyobjloader separates words by spaces and tabs only (found by fuzz_obj: "v\v" was a vertex to the
    // check but not to tinyobjloader, and the face indexed past the vertices read).
    expect_obj_error(dir.write("n.obj", "v 0 0 0\nv\v1 0 0\nv 0 1 0\nf 1 2 3\n"),
                     {"n.obj:2:", "control character 0x0b"});
    expect_obj_error(dir.write("o.obj", "v 0 0 0\nv 1 0 0\fv 0 1 0\nf 1 2 3\n"),
                     {"o.obj:2:", "control character 0x0c"});
    // Tabs do separate words.
    EXPECT_EQ(load_obj(dir.write("p.obj", "v\t0 0 0\nv 1\t0 0\nv 0 1 0\nf\t1 2 3\n")).surfaces.size(), 1u);
}

TEST(ObjLoader, BadMaterialsNameTheMtlLine) {
    TempDir dir;
    const std::string geometry = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n";
    dir.write("m.mtl", "newmtl x\nKd inf 0.5 0.5\n");
    expect_obj_error(dir.write("k.obj", geometry), {"m.mtl:2:", "reflectance (Kd) 'inf' must be finite"});
    dir.write("m.mtl", "newmtl x\nKd 0.5 0.5 0.5\nKe 1 -2 0\n");
    expect_obj_error(dir.write("l.obj", geometry), {"m.mtl:3:", "emission (Ke) '-2'"});
    dir.write("m.mtl", "newmtl x\nKd 0.5 nan 0.5\n");
    expect_obj_error(dir.write("n.obj", geometry), {"m.mtl:2:", "Kd"});
    dir.write("m.mtl", "newmtl x\nKe 1 1\n");
    expect_obj_error(dir.write("o.obj", geometry), {"m.mtl:2:", "three numbers"});
    dir.write("m.mtl", "newmtl x\nKd -0.1 0 0\n");
    expect_obj_error(dir.write("p.obj", geometry), {"m.mtl:2:", "'-0.1' must be finite and not negative"});
}

const std::string* warning_with(const Scene& scene, const std::string& text) {
    for (const std::string& w : scene.warnings)
        if (w.find(text) != std::string::npos) return &w;
    return nullptr;
}

// What real files get wrong without being broken: white as Kd 1, faces of two corners, the same face twice,
// transparency, two-sided parts as back-to-back faces. Each loads, with one warning per kind that counts it.
TEST(ObjLoader, SloppyFilesLoadWithOneWarningPerKind) {
    TempDir dir;
    dir.write(
        "m.mtl",
        "newmtl white\nKd 1 1 1\nnewmtl pink\nKd 1.0 0.5 0.5\nd 0.4\nnewmtl glass\nKd 0.2 0.2 0.2\nTr 0.9\n");
    const std::string obj = dir.write("s.obj",
                                      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                                      "o a\nusemtl white\nf 1 2 3 4\nf 1 2\nf 3\nf 2 3 4 1\n"
                                      "o b\nusemtl pink\nf 1 2 5\nf 5 1 2\nusemtl glass\nf 1 5 4\nf 4 5 1\n");
    const Scene scene = load_obj(obj);
    ASSERT_EQ(scene.surfaces.size(), 3u);
    expect_rgb(find_surface(scene, "a")->material.reflectance, glm::dvec3(kMaxReflectance));
    expect_rgb(find_surface(scene, "b/pink")->material.reflectance, glm::dvec3(kMaxReflectance, 0.5, 0.5));
    EXPECT_EQ(find_surface(scene, "a")->mesh.n_faces(), 1u);  // its repeat (another first corner) dropped
    EXPECT_EQ(find_surface(scene, "b/pink")->mesh.n_faces(), 1u);   // likewise
    EXPECT_EQ(find_surface(scene, "b/glass")->mesh.n_faces(), 2u);  // back to back: both kept, two-sided
    EXPECT_TRUE(find_surface(scene, "b/glass")->back_to_back);
    EXPECT_FALSE(find_surface(scene, "a")->back_to_back);
    ASSERT_EQ(scene.warnings.size(), 6u);
    EXPECT_TRUE(warning_with(scene, "1 pair(s) of back-to-back faces"));
    EXPECT_TRUE(warning_with(scene, "no material emits light"));
    EXPECT_TRUE(
        warning_with(scene, "2 material(s) reflect 1 or more (largest 1, first 'white'); clamped to 0.99"));
    EXPECT_TRUE(warning_with(scene, "2 material(s) are partly transparent (d < 1, first 'pink')"));
    EXPECT_TRUE(warning_with(scene, "skipped 2 face(s) of fewer than 3 corners"));
    EXPECT_TRUE(warning_with(scene, "dropped 2 duplicate face(s)"));
}

// A lamp written twice, in two objects and from another first corner, as exporters write them: the copy is
// dropped before coplanar faces are lifted (which would otherwise keep both, one in front of the other, and
// the lamp would emit twice).
TEST(ObjLoader, ALampWrittenTwiceInTwoObjectsEmitsOnce) {
    TempDir dir;
    dir.write("m.mtl", "newmtl lamp\nKd 0 0 0\nKe 1 1 1\nnewmtl white\nKd 0.5 0.5 0.5\n");
    const Scene scene =
        load_obj(dir.write("s.obj",
                           "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                           "o lamp\nusemtl lamp\nf 1 2 3 4\no lamp_copy\nusemtl lamp\nf 3 4 1 2\n"
                           "o other\nusemtl white\nf 4 1 2 3\n"));
    double emitting_area = 0.0;
    std::size_t faces = 0;
    for (const Surface& surface : scene.surfaces) {
        faces += surface.mesh.n_faces();
        if (surface.material.emits()) emitting_area += surface_area(surface.mesh);
    }
    EXPECT_EQ(faces, 1u);
    EXPECT_DOUBLE_EQ(emitting_area, 1.0);
    EXPECT_TRUE(warning_with(scene, "dropped 2 duplicate face(s)"));
    EXPECT_FALSE(warning_with(scene, "lies in the plane of"));
}

// A reflectance far above 1 looks like colours written from 0 to 255: the warning says so.
TEST(ObjLoader, ReflectanceOf255AsksAboutTheScale) {
    TempDir dir;
    dir.write("m.mtl", "newmtl orange\nKd 255 128 0\n");
    const Scene scene =
        load_obj(dir.write("o.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl orange\nf 1 2 3\n"));
    expect_rgb(scene.surfaces.at(0).material.reflectance, glm::dvec3(kMaxReflectance, kMaxReflectance, 0.0));
    EXPECT_TRUE(warning_with(scene, "(largest 255, first 'orange'); clamped to 0.99"));
    EXPECT_TRUE(warning_with(scene, "(were colours written from 0 to 255?)"));
}

// A positive index may name a vertex, texture coordinate or normal defined further down, as tinyobjloader
// resolves it; a negative one counts back from the line it is on.
TEST(ObjLoader, ForwardReferencesResolveAgainstTheWholeFile) {
    TempDir dir;
    const Scene scene =
        load_obj(dir.write("f.obj", "v 0 0 0\nf 1/1 2/2 3/3\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"));
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_DOUBLE_EQ(surface_area(scene.surfaces[0].mesh), 0.5);
    expect_obj_error(dir.write("g.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\n"),
                     {"g.obj:2:", "vertex index 3 is out of range (2 in the file)"});
    expect_obj_error(dir.write("h.obj", "v 0 0 0\nf 1 -2 3\nv 1 0 0\nv 0 1 0\n"),
                     {"h.obj:2:", "vertex index -2 is out of range (1 defined so far)"});
}

// tinyobjloader keeps a face's corner count in a byte: a disk of 256 or 300 corners (as CAD exporters write
// them) must keep all of them, and the faces after it their own.
TEST(ObjLoader, FacesOfMoreThan255CornersKeepEveryCorner) {
    for (const int n : {255, 256, 300}) {
        SCOPED_TRACE(n);
        TempDir dir;
        std::string text;
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * 3.141592653589793 * k / n;
            text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
        }
        text += "v 3 0 0\nv 4 0 0\nv 4 1 0\nf";
        for (int k = 1; k <= n; ++k) text += " " + std::to_string(k);
        text +=
            "\nf " + std::to_string(n + 1) + " " + std::to_string(n + 2) + " " + std::to_string(n + 3) + "\n";
        const Scene scene = load_obj(dir.write("disk.obj", text));
        ASSERT_EQ(scene.surfaces.size(), 1u);
        EXPECT_FALSE(warning_with(scene, "dropped"));
        // The polygon's area, n/2 sin(2π/n), plus the triangle's 1/2 (coordinates written to 6 decimals).
        const double disk = 0.5 * n * std::sin(2.0 * 3.141592653589793 / n);
        EXPECT_NEAR(surface_area(scene.surfaces[0].mesh), disk + 0.5, 1e-5);
    }
}

TEST(ObjLoader, CommandLineExitsWithStatus2AndOneLine) {
    TempDir dir;
    const std::string bad = dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 7\n");
    const auto result = test::run_radiosity({"info", bad});
    EXPECT_EQ(result.status, 2);
    EXPECT_NE(result.err.find("bad.obj:4: vertex index 7 is out of range"), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_TRUE(result.out.empty());
}

TEST(ObjLoader, PublishedCornellBoxAssetLoads) {
    const Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/cornell_box.obj");
    EXPECT_EQ(scene.surfaces.size(), 8u);
    const Surface* light = find_surface(scene, "light");
    ASSERT_NE(light, nullptr);
    expect_rgb(light->material.emission, glm::dvec3(17, 12, 4));
    // The published ceiling is the full quad, overlapping the light.
    EXPECT_NEAR(surface_area(find_surface(scene, "ceiling")->mesh), 556.0 * 559.2, 1e-6);
}

}  // namespace
}  // namespace rad
