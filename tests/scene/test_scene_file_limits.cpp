// The limits on what one scene file may hold (core/src/scene_limits.hpp) are checked while reading, at the
// line or header that goes beyond them, before anything is allocated for the excess. The real limits are
// millions; these tests give the same checks small ones.
#include <gtest/gtest.h>

#include <string>

#include "expect_input_error.hpp"
#include "scene/obj/obj_syntax.hpp"
#include "scene/ply/ply_check.hpp"

namespace rad {
namespace {

SceneFileLimits small_limits() {
    SceneFileLimits limits;
    limits.vertices = 4;
    limits.faces = 2;
    limits.face_corners = 7;
    return limits;
}

void expect_obj_refused(const std::string& text, std::initializer_list<std::string> parts) {
    test::expect_input_error([&](const std::string& p) { check_obj_text(text, p, small_limits()); }, "s.obj",
                             parts);
}

const std::string kFourVertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

TEST(SceneFileLimits, ObjAtTheLimitsIsAccepted) {
    EXPECT_NO_THROW(check_obj_text(kFourVertices + "f 1 2 3 4\nf 1 2 3\n", "s.obj", small_limits()));
}

TEST(SceneFileLimits, ObjBeyondEachLimitIsRefusedAtItsLine) {
    expect_obj_refused(kFourVertices + "v 0 0 1\n", {"s.obj:5:", "more than 4 vertices"});
    expect_obj_refused(kFourVertices + "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n",
                       {"s.obj:9:", "more than 4 normals"});
    expect_obj_refused(kFourVertices + "f 1 2 3\nf 1 2 3\nf 1 2 3\n", {"s.obj:7:", "more than 2 faces"});
    expect_obj_refused(kFourVertices + "f 1 2 3 4\nf 1 2 3 4\n", {"s.obj:6:", "more than 7 face corners"});
}

TEST(SceneFileLimits, ObjRepeatedLibrariesAreReadOnceAndTheirNumberIsBounded) {
    const ObjFacts facts =
        check_obj_text("mtllib a.mtl\nmtllib a.mtl b.mtl a.mtl\n" + kFourVertices, "s.obj");
    ASSERT_EQ(facts.libraries.size(), 2u);
    EXPECT_EQ(facts.libraries[1].name, "b.mtl");
    std::string many;
    for (std::size_t i = 0; i <= kMaxMaterialLibraries; ++i)
        many += "mtllib m" + std::to_string(i) + ".mtl\n";
    test::expect_input_error(
        [&](const std::string& p) { check_obj_text(many, p); }, "s.obj",
        {"s.obj:" + std::to_string(kMaxMaterialLibraries + 1) + ":", "material libraries"});
}

std::string ply(std::size_t vertices, std::size_t faces, const std::string& body) {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list uchar int vertex_indices\nend_header\n" + body;
}

void expect_ply_refused(const std::string& bytes, std::initializer_list<std::string> parts) {
    test::expect_input_error([&](const std::string& p) { check_ply(p, bytes, small_limits()); }, "s.ply",
                             parts);
}

TEST(SceneFileLimits, PlyCountsBeyondTheLimitsAreRefusedFromTheHeader) {
    const std::string square = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
    EXPECT_NO_THROW(check_ply("s.ply", ply(4, 2, square + "4 0 1 2 3\n3 0 1 2\n"), small_limits()));
    expect_ply_refused(ply(5, 1, square + "0 0 1\n3 0 1 2\n"), {"s.ply", "5 vertices", "limit", "4"});
    expect_ply_refused(ply(4, 3, square + "3 0 1 2\n3 0 1 2\n3 0 1 2\n"), {"s.ply", "3 faces", "limit", "2"});
    expect_ply_refused(ply(4, 2, square + "4 0 1 2 3\n4 0 1 2 3\n"),
                       {"s.ply:15:", "more than 7 face corners"});
}

}  // namespace
}  // namespace rad
