// The camera a scene without one of its own is framed from: the published Cornell box, open at z = 0 with
// every wall facing inwards, is seen through its opening with both side walls from the front; a closed
// box and a scene with a camera keep theirs.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "rad/camera/camera_view.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

// Whether each face of the surface faces the eye (its front normal towards it).
bool faces_eye(const Surface& surface, const glm::dvec3& eye) {
    for (auto face : surface.mesh.faces()) {
        const auto normal = surface.mesh.calc_face_normal(face);
        const glm::dvec3 corner = to_glm(surface.mesh.point(*surface.mesh.cfv_begin(face)));
        if (glm::dot(glm::dvec3(normal[0], normal[1], normal[2]), eye - corner) <= 0.0) return false;
    }
    return true;
}

const Surface& surface_named(const Scene& scene, const std::string& name) {
    for (const Surface& surface : scene.surfaces)
        if (surface.name.find(name) != std::string::npos) return surface;
    throw std::runtime_error("no surface " + name);
}

TEST(SceneCamera, AnOpenRoomIsSeenThroughItsOpening) {
    const Scene scene = load_scene(std::string(RAD_SOURCE_DIR) + "/assets/cornell_box.obj");
    ASSERT_FALSE(scene.camera);
    const Camera camera = scene_camera(scene);
    EXPECT_LT(camera.eye.z, 0.0);  // in front of the opening, not behind the back wall (z = 559)
    for (const char* wall : {"back", "left", "right", "floor"})
        EXPECT_TRUE(faces_eye(surface_named(scene, wall), camera.eye)) << wall;
}

TEST(SceneCamera, AClosedBoxKeepsTheUsualView) {
    const test::TempDir folder;
    folder.write("box.mtl", "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\n");
    const std::string header = std::string("mtllib box.mtl\nusemtl white\n") + test::kInwardUnitCubeCorners;
    const std::string path =
        folder.write("box.obj", header + test::kInwardUnitCubeFirstFace + test::kInwardUnitCubeOtherFaces);
    const Scene scene = load_scene(path);
    ASSERT_FALSE(scene.camera);
    const Camera usual = frame_bounding_box(bounding_box(scene));
    EXPECT_NEAR(glm::length(scene_camera(scene).eye - usual.eye), 0.0, 1e-9);
    // Without its back wall (the first face, at z = 0) the box is open towards -z, and seen from there.
    const std::string open = folder.write("open.obj", header + test::kInwardUnitCubeOtherFaces);
    EXPECT_LT(scene_camera(load_scene(open)).eye.z, 0.0);
}

}  // namespace
}  // namespace rad
