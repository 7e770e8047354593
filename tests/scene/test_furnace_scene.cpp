// builtin:furnace and builtin:furnace-N: the face counts asked for, a closed room whose every face looks into
// the room (walls inward, balls outward), one material everywhere, and bad counts refused in one line naming
// the scene.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "expect_input_error.hpp"
#include "rad/scene/builtin_scenes.hpp"

namespace rad {
namespace {

// A furnace meets its face count to half a ball: balls are whole, of 224 faces each.
constexpr double kFaceTolerance = 112.0;

std::size_t face_count(const Scene& scene) {
    std::size_t faces = 0;
    for (const Surface& s : scene.surfaces) faces += s.mesh.n_faces();
    return faces;
}

TEST(Furnace, FaceCountsAreTheRequestedOnes) {
    for (const auto& [name, faces] :
         {std::pair{"furnace", std::size_t{10'000}}, std::pair{"furnace-1k", std::size_t{1'000}},
          std::pair{"furnace-12345", std::size_t{12'345}}, std::pair{"furnace-30k", std::size_t{30'000}}}) {
        const Scene scene = make_builtin_scene(name);
        EXPECT_NEAR(static_cast<double>(face_count(scene)), static_cast<double>(faces), kFaceTolerance)
            << name;
        EXPECT_EQ(face_count(scene), sphere_room_faces(furnace_room(faces))) << name;
        EXPECT_EQ(scene.source, std::string("builtin:") + name);
    }
    // The large ones by count alone, which is what make_sphere_room makes (checked above).
    for (std::size_t faces : {std::size_t{100'000}, std::size_t{1'000'000}, std::size_t{10'000'000}}) {
        EXPECT_NEAR(static_cast<double>(sphere_room_faces(furnace_room(faces))), static_cast<double>(faces),
                    kFaceTolerance)
            << faces;
    }
}

// Every wall's normal points into the room, every ball face's away from its ball's centre (the centre of the
// grid cell holding it), every ball is a closed mesh with no boundary edge, and everything has the furnace's
// material.
TEST(Furnace, IsClosedWithEveryFaceLookingIntoTheRoom) {
    const SphereRoom room = furnace_room(10'000);
    const Scene scene = make_sphere_room(room);
    ASSERT_EQ(scene.surfaces.size(), 2u);
    std::size_t walls = 0, ball_faces = 0;
    for (const Surface& s : scene.surfaces) {
        EXPECT_EQ(s.material.reflectance, glm::dvec3(kFurnaceReflectance));
        EXPECT_NEAR(s.material.emission.x * std::numbers::pi, kFurnaceEmission, 1e-15);
        const bool is_room = s.name == "room";
        for (auto f : s.mesh.faces()) {
            const glm::dvec3 normal = to_glm(s.mesh.calc_face_normal(f));
            const glm::dvec3 centroid = to_glm(s.mesh.calc_face_centroid(f));
            if (is_room) {
                ++walls;
                EXPECT_GT(glm::dot(normal, glm::dvec3(0.5) - centroid), 0.0);
            } else {
                ++ball_faces;
                const glm::dvec3 centre =
                    (glm::floor(centroid * double(room.spheres)) + 0.5) / double(room.spheres);
                EXPECT_GT(glm::dot(normal, glm::normalize(centroid - centre)), 0.9);
            }
        }
        if (!is_room) {
            for (auto e : s.mesh.edges()) ASSERT_FALSE(s.mesh.is_boundary(e)) << "a ball has a hole";
        }
    }
    EXPECT_EQ(walls, 6u);
    EXPECT_EQ(ball_faces, room.balls * 224);
}

TEST(Furnace, BadFaceCountsAreRefusedNamingTheScene) {
    for (const char* name :
         {"furnace-", "furnace-abc", "furnace-10x", "furnace-1K", "furnace-1.5k", "furnace--5", "furnace-+5",
          "furnace- 5k", "furnace-5k ", "furnace-010k", "furnace-0", "furnace-999", "furnace-10001k",
          "furnace-11m", "furnace-99999999999999999999999", "furnace-100kk"}) {
        test::expect_input_error([](const std::string& n) { make_builtin_scene(n); }, name,
                                 {std::string("builtin:") + name + ":"});
    }
    test::expect_input_error([](const std::string&) { make_furnace(999); }, "",
                             {"builtin:furnace-999", "1000"});
}

TEST(Furnace, TheUnknownNameMessageNamesFurnaceN) {
    test::expect_input_error([](const std::string& n) { make_builtin_scene(n); }, "furnaces", {"furnace-N"});
}

}  // namespace
}  // namespace rad
