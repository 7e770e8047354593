// Hard cases seen in images (this program opens an OpenGL context, hence its name). The published Cornell
// box's light lies in its ceiling's plane: without care the depth test picks the ceiling or the light pixel
// by pixel (z-fighting blotches) or hides the light. The loader moves the light a thousandth of the scene's
// diagonal in front of the ceiling (test_hard_coplanar.cpp), so from any camera every pixel of the light
// shows the light, at least its emitted radiance Le and uniform, and the light is counted once.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "rad/camera/camera_view.hpp"
#include "rad/io/image_file.hpp"
#include "rad/scene/scene_loader.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

const std::string kCornell = std::string(RAD_SOURCE_DIR) + "/assets/cornell_box.obj";
constexpr int kSize = 160;

struct View {
    std::string name;
    std::string camera;  // --camera
    double fov;
};

// The light's corners on the image, in pixels (x right, y down), as the renderer projects them.
std::vector<glm::dvec2> light_on_image(const Scene& scene, const Camera& camera) {
    const glm::mat4 m = view_projection(camera, 1.0, bounding_box(scene));
    for (const Surface& s : scene.surfaces) {
        if (s.name != "light") continue;
        std::vector<glm::dvec2> out;
        for (auto f : s.mesh.faces()) {
            for (auto v : s.mesh.fv_range(f)) {
                const auto p = s.mesh.point(v);
                const glm::vec4 clip = m * glm::vec4(float(p[0]), float(p[1]), float(p[2]), 1.0f);
                out.push_back({(clip.x / clip.w + 1.0) * 0.5 * kSize, (1.0 - clip.y / clip.w) * 0.5 * kSize});
            }
        }
        return out;
    }
    return {};
}

// Whether q lies inside the convex polygon, at least `margin` from each of its edges.
bool inside(const std::vector<glm::dvec2>& polygon, const glm::dvec2& q, double margin) {
    double sign = 0.0;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const glm::dvec2 a = polygon[k], b = polygon[(k + 1) % polygon.size()];
        const glm::dvec2 edge = b - a;
        const double cross = (edge.x * (q.y - a.y) - edge.y * (q.x - a.x)) / glm::length(edge);
        if (sign == 0.0) sign = cross > 0.0 ? 1.0 : -1.0;
        if (cross * sign < margin) return false;
    }
    return true;
}

void PrintTo(const View& view, std::ostream* out) {
    *out << view.name;
}

class CoplanarLightImage : public ::testing::TestWithParam<View> {};

TEST_P(CoplanarLightImage, EveryLightPixelShowsTheLightOnceAndEvenly) {
    const View& view = GetParam();
    test::TempDir dir;
    const std::string out = (dir.path() / "light.pfm").string();
    const test::CommandResult result =
        test::run_radiosity({"render", kCornell, "--patch-size", "100", "--rays", "1024", "--width",
                             std::to_string(kSize), "--height", std::to_string(kSize), "--camera",
                             view.camera, "--fov", std::to_string(view.fov), "--out", out});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("the emitter 'light' lies in the plane of 'ceiling'"), std::string::npos)
        << result.err;
    const Image image = read_image(out);
    ASSERT_EQ(image.width, kSize);

    const Scene scene = load_scene(kCornell);
    Camera camera;
    std::array<double, 9> v{0, 0, 0, 0, 0, 0, 0, 1, 0};
    ASSERT_GE(std::sscanf(view.camera.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2],
                          &v[3], &v[4], &v[5], &v[6], &v[7], &v[8]),
              6);
    camera.eye = {v[0], v[1], v[2]};
    camera.target = {v[3], v[4], v[5]};
    camera.up = {v[6], v[7], v[8]};
    camera.fov_degrees = view.fov;
    const std::vector<glm::dvec2> light = light_on_image(scene, camera);
    ASSERT_EQ(light.size(), 4u);

    // Le = 17 12 4; what the light shows is B / π = Le + ρ H / π, a little more where the room lights it.
    const glm::vec3 le(17.0f, 12.0f, 4.0f);
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(0.0f);
    int count = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!inside(light, {x + 0.5, y + 0.5}, 1.5)) continue;
            const glm::vec3 p = image.pixels[std::size_t(y) * kSize + x];
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            ++count;
        }
    }
    std::printf("[ figures  ] %s: %d light pixels, red from %.4f to %.4f (Le 17)\n", view.name.c_str(), count,
                lo.r, hi.r);
    ASSERT_GT(count, 40);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(lo[c], le[c] * (1.0f - 1e-5f))
            << "channel " << c << ": a pixel of the light shows something else";
        EXPECT_LE(hi[c], lo[c] * 1.02f) << "channel " << c << ": the light is not even";
        EXPECT_LE(hi[c], le[c] * 1.05f) << "channel " << c << ": more than the light's own radiance";
    }
}

INSTANTIATE_TEST_SUITE_P(Views, CoplanarLightImage,
                         ::testing::Values(View{"published", "278,273,-800,278,273,-799", 39.3},
                                           View{"below", "278,300,280,278,548.8,280,0,0,1", 60.0},
                                           View{"grazing", "540,30,20,278,548,280", 30.0},
                                           View{"close_under_the_ceiling", "100,500,100,278,548,280", 50.0}),
                         [](const auto& info) { return info.param.name; });

// A rug modelled in the floor's plane (two surfaces, neither emitting) ties with the floor in the depth test
// and for rays: seen from above, the rug's pixels speckled with the floor's grey. The loader moves the
// smaller surface, the rug, in front of the floor: every pixel well inside it shows the rug's red.
TEST(CoplanarRugImage, EveryRugPixelShowsTheRug) {
    const test::TempDir folder;
    folder.write("rug.mtl",
                 "newmtl floor\nKd 0.5 0.5 0.5\nnewmtl rug\nKd 0.7 0.05 0.05\n"
                 "newmtl lamp\nKd 0.5 0.5 0.5\nKe 5 5 5\n");
    const std::string scene =
        folder.write("rug.obj",
                     "mtllib rug.mtl\n"
                     "v 0 0 0\nv 0 0 2\nv 2 0 2\nv 2 0 0\n"                  // the floor, facing up
                     "v 0.5 0 0.5\nv 0.5 0 1.5\nv 1.5 0 1.5\nv 1.5 0 0.5\n"  // the rug in its plane
                     "v 0 2 0\nv 2 2 0\nv 2 2 2\nv 0 2 2\n"                  // the lamp above, facing down
                     "o floor\nusemtl floor\nf 1 2 3 4\no rug\nusemtl rug\nf 5 6 7 8\no lamp\nusemtl lamp\nf "
                     "9 10 11 12\n");
    const std::string out = (folder.path() / "rug.png").string();
    const test::CommandResult result = test::run_program(
        RAD_BINARY, {"render", scene, "--width", std::to_string(kSize), "--height", std::to_string(kSize),
                     "--camera", "1,1.9,1,1,0,1,0,0,-1", "--fov", "60", "--out", out});
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_NE(result.err.find("'rug' lies in the plane of 'floor'"), std::string::npos) << result.err;
    const Image image = read_image(out);
    // The rug spans ±0.5 around the centre seen from 1.9 above at 60°: ±0.5 / (1.9 tan 30°) of the half
    // width, 36 pixels; 30 keeps off its edges.
    int grey = 0, pixels = 0;
    for (int y = kSize / 2 - 30; y < kSize / 2 + 30; ++y) {
        for (int x = kSize / 2 - 30; x < kSize / 2 + 30; ++x) {
            const glm::vec3& p = image.at(x, y);
            ++pixels;
            if (!(p.r > 2.0f * p.g)) ++grey;  // sRGB codes: the rug about 2.8 times, the floor 1
        }
    }
    EXPECT_EQ(grey, 0) << "of " << pixels << " pixels inside the rug";
}

}  // namespace
}  // namespace rad
