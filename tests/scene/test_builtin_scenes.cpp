// The built-in scenes match their published or stated geometry, materials and orientation.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <numbers>

#include "rad/geometry/polygon.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/util/error.hpp"

namespace rad {
namespace {

const Surface& surface_named(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces) {
        if (s.name == name) return s;
    }
    throw std::runtime_error("no surface " + name);
}

BoundingBox surface_box(const Surface& s) {
    BoundingBox box;
    for (auto v : s.mesh.vertices()) box.extend(to_glm(s.mesh.point(v)));
    return box;
}

TEST(CornellBox, MatchesPublishedDimensions) {
    const Scene scene = make_cornell_box();
    ASSERT_EQ(scene.surfaces.size(), 8u);
    const BoundingBox box = bounding_box(scene);
    EXPECT_EQ(box.min, glm::dvec3(0.0, 0.0, 0.0));
    EXPECT_EQ(box.max, glm::dvec3(556.0, 548.8, 559.2));

    const BoundingBox light = surface_box(surface_named(scene, "light"));
    EXPECT_EQ(light.min, glm::dvec3(213.0, 548.8, 227.0));
    EXPECT_EQ(light.max, glm::dvec3(343.0, 548.8, 332.0));
    EXPECT_NEAR(surface_area(surface_named(scene, "light").mesh), 130.0 * 105.0, 1e-9);
    EXPECT_EQ(surface_box(surface_named(scene, "tall block")).max.y, 330.0);
    EXPECT_EQ(surface_box(surface_named(scene, "short block")).max.y, 165.0);
}

TEST(CornellBox, CeilingHasTheLightsOpeningCutOut) {
    const Scene scene = make_cornell_box();
    const double ceiling = surface_area(surface_named(scene, "ceiling").mesh);
    EXPECT_NEAR(ceiling, 556.0 * 559.2 - 130.0 * 105.0, 1e-6);
    // Nothing of the ceiling covers the opening: no ceiling face's centroid lies inside it.
    const SurfaceMesh& mesh = surface_named(scene, "ceiling").mesh;
    for (auto f : mesh.faces()) {
        const auto c = mesh.calc_face_centroid(f);
        const bool inside = c[0] > 213.0 && c[0] < 343.0 && c[2] > 227.0 && c[2] < 332.0;
        EXPECT_FALSE(inside);
    }
}

TEST(CornellBox, MaterialsArePublishedOnes) {
    const Scene scene = make_cornell_box();
    EXPECT_EQ(surface_named(scene, "light").material.emission, glm::dvec3(17.0, 12.0, 4.0));
    EXPECT_EQ(surface_named(scene, "left wall").material.reflectance, glm::dvec3(0.63, 0.065, 0.05));
    EXPECT_EQ(surface_named(scene, "right wall").material.reflectance, glm::dvec3(0.14, 0.45, 0.091));
    EXPECT_EQ(surface_named(scene, "floor").material.reflectance, glm::dvec3(0.725, 0.71, 0.68));
    EXPECT_FALSE(surface_named(scene, "floor").material.emits());
}

TEST(CornellBox, EveryWallFacesIntoTheBox) {
    const Scene scene = make_cornell_box();
    const PatchMesh patches = build_patches(scene, {100.0});
    const glm::dvec3 centre(278.0, 274.4, 279.6);
    for (const char* name : {"floor", "ceiling", "light", "back wall", "left wall", "right wall"}) {
        for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
            if (scene.surfaces[s].name != name) continue;
            for (auto p = patches.surface_begin[s]; p < patches.surface_begin[s + 1]; ++p) {
                const Patch& patch = patches.patches[p];
                EXPECT_GT(glm::dot(patch.normal, centre - patch.centroid), 0.0) << name;
            }
        }
    }
}

TEST(CornellBox, CameraIsThePublishedOneAndSeesRedOnTheLeft) {
    const Scene scene = make_cornell_box();
    ASSERT_TRUE(scene.camera.has_value());
    const Camera& camera = *scene.camera;
    EXPECT_EQ(camera.eye, glm::dvec3(278, 273, -800));
    EXPECT_NEAR(camera.fov_degrees, 2.0 * std::atan(12.5 / 35.0) * 180.0 / std::numbers::pi, 1e-4);

    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    auto horizontal = [&](const std::string& name) {
        const BoundingBox b = surface_box(surface_named(scene, name));
        return glm::dot((b.min + b.max) * 0.5 - camera.eye, right);
    };
    EXPECT_LT(horizontal("left wall"), 0.0);   // red, on the left of the image
    EXPECT_GT(horizontal("right wall"), 0.0);  // green, on the right
    const double up = glm::dot(surface_box(surface_named(scene, "light")).min - camera.eye, camera.up);
    EXPECT_GT(up, 0.0);  // the light is above the eye
}

TEST(TestScenes, CubeIsClosedWithOneEmittingFace) {
    const Scene scene = make_cube();
    ASSERT_EQ(scene.surfaces.size(), 6u);
    EXPECT_DOUBLE_EQ(total_area(scene), 6.0);
    int emitters = 0;
    for (const Surface& s : scene.surfaces) {
        EXPECT_EQ(s.material.reflectance, glm::dvec3(0.5));
        if (s.material.emits()) {
            ++emitters;
            EXPECT_NEAR(s.material.emitted_radiosity().x, 1.0, 1e-15);
        }
    }
    EXPECT_EQ(emitters, 1);
    // Seen from inside: every face's normal points to the centre.
    const PatchMesh patches = build_patches(scene, {1.0});
    ASSERT_EQ(patches.size(), 6u);
    for (const Patch& p : patches.patches) {
        EXPECT_NEAR(glm::dot(p.normal, glm::normalize(glm::dvec3(0.5) - p.centroid)), 1.0, 1e-12);
    }
}

TEST(TestScenes, WhiteRoomIsTheCornellBoxClosedAndWhite) {
    const Scene room = make_white_room();
    const Scene cornell = make_cornell_box();
    ASSERT_EQ(room.surfaces.size(), cornell.surfaces.size() + 1);
    const double front_wall =
        0.5 * (552.8 + 556.0) * 548.8;  // a trapezoid: the left wall leans out by 3.2 mm
    EXPECT_NEAR(total_area(room), total_area(cornell) + front_wall, 1e-6 * total_area(room));
    for (const Surface& s : room.surfaces) {
        EXPECT_EQ(s.material.reflectance, s.material.emits() ? glm::dvec3(0.78) : glm::dvec3(0.95)) << s.name;
    }
    // Closed: no hemisphere ray leaves. (Rows do not all sum to 1: the floor under the blocks sees only their
    // insides, which block.)
    const PatchMesh patches = build_patches(room, {140.0});
    FormFactorReport report;
    FormFactorOptions options;
    options.rays = 1024;
    compute_form_factors(patches, options, &report);
    EXPECT_LT(report.escaped_ray_fraction, 1e-5);
    EXPECT_NEAR(report.max_row_sum, 1.0, 1e-3);
    ASSERT_TRUE(room.camera.has_value());
    EXPECT_LT(room.camera->eye.z, 559.2);
    EXPECT_GT(room.camera->eye.z, 0.0);
}

TEST(TestScenes, ManyLightsSpreadsThePublishedLightsPowerOver144LampsFacingDown) {
    const Scene scene = make_many_lights_box();
    const Scene cornell = make_cornell_box();
    glm::dvec3 power(0.0), published(0.0);
    for (const Surface& s : scene.surfaces) power += s.material.emitted_radiosity() * surface_area(s.mesh);
    for (const Surface& s : cornell.surfaces)
        published += s.material.emitted_radiosity() * surface_area(s.mesh);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(power[c], published[c], 1e-9 * published[c]);
    // At the default patch size every lamp is one patch, facing the floor, under the ceiling.
    const PatchMesh patches = build_patches(scene, {});
    std::size_t lamps = 0;
    for (const Patch& p : patches.patches) {
        if (!scene.surfaces[p.surface].material.emits()) continue;
        ++lamps;
        EXPECT_NEAR(p.normal.y, -1.0, 1e-12);
        EXPECT_NEAR(p.area, 400.0, 1e-9);
        EXPECT_LT(p.centroid.y, 548.8);
    }
    EXPECT_EQ(lamps, 144u);
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->eye, cornell.camera->eye);
}

TEST(TestScenes, SquaresFaceEachOther) {
    for (const Scene& scene : {make_parallel_squares(), make_perpendicular_squares()}) {
        const PatchMesh patches = build_patches(scene, {1.0});
        ASSERT_EQ(patches.size(), 2u);
        const Patch& a = patches.patches[0];
        const Patch& b = patches.patches[1];
        EXPECT_DOUBLE_EQ(a.area, 1.0);
        EXPECT_DOUBLE_EQ(b.area, 1.0);
        EXPECT_GT(glm::dot(a.normal, b.centroid - a.centroid), 0.0) << scene.source;
        EXPECT_GT(glm::dot(b.normal, a.centroid - b.centroid), 0.0) << scene.source;
    }
}

TEST(BuiltinScenes, UnknownNameListsTheAvailableOnes) {
    try {
        make_builtin_scene("nope");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("builtin:nope"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("cornell"), std::string::npos);
    }
    for (const auto& info : builtin_scenes()) EXPECT_NO_THROW(make_builtin_scene(info.name));
}

}  // namespace
}  // namespace rad
