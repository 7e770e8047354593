// Illuminance at sensors from a solution (sensor_irradiance), against closed forms: a point under a luminous
// rectangle, the sky through a roof opening into a black room, the sun's E cos θ and its shadow, and any
// point of a closed furnace, where the irradiance is the uniform radiosity itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "rad/measure/sensor_irradiance.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"
#include "solved_scene.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

// An OBJ of quads, each written so its front faces `inside`, all of material `black` (ρ 0) unless named.
class ObjQuads {
  public:
    void add(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d, const glm::dvec3& inside,
             const std::string& material = "black") {
        if (glm::dot(glm::cross(b - a, c - a), inside - a) < 0.0) std::swap(b, d);
        text_ << "usemtl " << material << '\n';
        for (const glm::dvec3& p : {a, b, c, d}) text_ << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
        text_ << "f -4 -3 -2 -1\n";
    }
    // Writes the OBJ and its materials and loads them.
    Scene load(const test::TempDir& dir, const std::string& materials) const {
        dir.write("scene.mtl", "newmtl black\nKd 0 0 0\n" + materials);
        return load_scene(dir.write("scene.obj", "mtllib scene.mtl\n" + text_.str()));
    }

  private:
    std::ostringstream text_;
};

// The factor from a point to a rectangle parallel to its plane, at height h, with a corner above the point
// and sides a and b (the closed form for a corner: Howell's catalogue, C-11).
double corner_factor(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1.0 + x * x), sy = std::sqrt(1.0 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2.0 * std::numbers::pi);
}

// The factor from point (px, pz) to the rectangle [x0, x1] × [z0, z1] at height h above it, by adding and
// taking away corner rectangles.
double rectangle_factor(double px, double pz, double x0, double x1, double z0, double z1, double h) {
    const auto g = [&](double x, double z) {
        const double a = x - px, b = z - pz;
        return (a < 0 ? -1.0 : 1.0) * (b < 0 ? -1.0 : 1.0) * corner_factor(std::abs(a), std::abs(b), h);
    };
    return g(x1, z1) - g(x0, z1) - g(x1, z0) + g(x0, z0);
}

struct Measured {
    std::unique_ptr<test::SolvedScene> solved;
    std::vector<SensorIrradiance> light;
};

Measured measure(Scene scene, double patch_size, const std::vector<Sensor>& sensors) {
    Measured m{test::solve_scene(std::move(scene), Subdivision::uniform, patch_size), {}};
    const Solution solution = test::solution_of(*m.solved, patch_size);
    const RayScene rays(*solution.elements);
    m.light = sensor_irradiance(m.solved->scene, solution, rays, sensors);
    return m;
}

std::vector<Sensor> floor_grid(double x0, double x1, double z0, double z1, int n) {
    std::vector<Sensor> sensors;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            sensors.push_back(
                {{x0 + (x1 - x0) * (i + 0.5) / n, 0.0, z0 + (z1 - z0) * (j + 0.5) / n}, {0.0, 1.0, 0.0}});
    return sensors;
}

TEST(SensorIrradiance, UnderALuminousRectangleIsTheClosedForm) {
    const test::TempDir dir;
    ObjQuads obj;
    obj.add({-4, 0, -4}, {5, 0, -4}, {5, 0, 5}, {-4, 0, 5}, {0, 1, 0});      // a black floor
    obj.add({0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, {0, 0, 0}, "lamp");  // 1 m² facing down
    const Scene scene = obj.load(dir, "newmtl lamp\nKd 0 0 0\nKe 2 2 2\n");
    const std::vector<Sensor> sensors = floor_grid(-0.5, 1.5, -0.5, 1.5, 6);
    const Measured m = measure(scene, 0.5, sensors);
    double worst = 0.0;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
        const glm::dvec3& p = sensors[k].point;
        const double exact = 2.0 * std::numbers::pi * rectangle_factor(p.x, p.z, 0, 1, 0, 1, 1.0);
        worst = std::max(worst, std::abs(m.light[k].total().y - exact) / exact);
        EXPECT_EQ(m.light[k].sky, glm::dvec3(0.0));
    }
    EXPECT_LT(worst, 0.005);
}

TEST(SensorIrradiance, TheSkyThroughARoofOpeningIsTheClosedForm) {
    // A black room 4 × 4 × 3 m with a 1 m² opening in the middle of its roof, under a uniform sky of L = 1:
    // on the floor H = π L F, F the factor to the opening.
    const test::TempDir dir;
    ObjQuads obj;
    const glm::dvec3 in{2.0, 1.5, 2.0};
    obj.add({0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}, in);
    obj.add({0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}, in);
    obj.add({0, 0, 4}, {4, 0, 4}, {4, 3, 4}, {0, 3, 4}, in);
    obj.add({0, 0, 0}, {0, 0, 4}, {0, 3, 4}, {0, 3, 0}, in);
    obj.add({4, 0, 0}, {4, 0, 4}, {4, 3, 4}, {4, 3, 0}, in);
    obj.add({0, 3, 0}, {4, 3, 0}, {4, 3, 1.5}, {0, 3, 1.5}, in);
    obj.add({0, 3, 2.5}, {4, 3, 2.5}, {4, 3, 4}, {0, 3, 4}, in);
    obj.add({0, 3, 1.5}, {1.5, 3, 1.5}, {1.5, 3, 2.5}, {0, 3, 2.5}, in);
    obj.add({2.5, 3, 1.5}, {4, 3, 1.5}, {4, 3, 2.5}, {2.5, 3, 2.5}, in);
    Scene scene = obj.load(dir, "");
    scene.sky.kind = Sky::Kind::uniform;
    scene.sky.radiance = glm::dvec3(1.0);
    const std::vector<Sensor> sensors = floor_grid(0.0, 4.0, 0.0, 4.0, 10);
    const Measured m = measure(scene, 0.5, sensors);
    double worst = 0.0, mean = 0.0;
    for (std::size_t k = 0; k < sensors.size(); ++k) {
        const glm::dvec3& p = sensors[k].point;
        const double exact = std::numbers::pi * rectangle_factor(p.x, p.z, 1.5, 2.5, 1.5, 2.5, 3.0);
        const double error = std::abs(m.light[k].total().y - exact) / exact;
        worst = std::max(worst, error);
        mean += error / static_cast<double>(sensors.size());
    }
    std::printf("sky component: mean error %.3f %%, worst %.3f %%\n", 100.0 * mean, 100.0 * worst);
    EXPECT_LT(mean, 0.01);
    EXPECT_LT(worst, 0.03);
}

TEST(SensorIrradiance, TheSunIsECosThetaWithItsShadow) {
    const test::TempDir dir;
    ObjQuads obj;
    obj.add({-2, 0, -2}, {4, 0, -2}, {4, 0, 4}, {-2, 0, 4}, {0, 1, 0});
    obj.add({0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, {0, 0, 0});  // a black plate above the floor
    Scene scene = obj.load(dir, "");
    scene.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
    scene.sun.irradiance = glm::dvec3(2.0);
    const std::vector<Sensor> sensors = {{{3.0, 0.0, 3.0}, {0.0, 1.0, 0.0}},  // in the sun
                                         {{0.2, 0.0, 0.3}, {0.0, 1.0, 0.0}},  // in the plate's shadow
                                         {{3.0, 0.5, 3.0}, glm::normalize(glm::dvec3(1.0, 0.0, 1.0))},
                                         {{3.0, 0.5, 3.0}, {0.0, -1.0, 0.0}}};  // facing away from the sun
    const Measured m = measure(scene, 0.5, sensors);
    const glm::dvec3 d = scene.sun.direction;
    EXPECT_NEAR(m.light[0].sun.y, 2.0 * d.y, 1e-12);
    EXPECT_EQ(m.light[1].sun.y, 0.0);
    EXPECT_NEAR(m.light[2].sun.y, 2.0 * glm::dot(d, sensors[2].direction), 1e-12);
    EXPECT_EQ(m.light[3].sun.y, 0.0);
}

TEST(SensorIrradiance, AnyPointInAClosedFurnaceReceivesItsUniformRadiosity) {
    // Every face has ρ 0.5 and E 1, so B = 2 everywhere and every direction sees B = 2: H = 2.
    const auto solved = test::solve_scene(make_furnace(1000), Subdivision::uniform);
    const Solution solution = test::solution_of(*solved, 0.0);
    const RayScene rays(*solution.elements);
    std::vector<Sensor> sensors;
    for (std::size_t q = 0; q < solution.size(); q += solution.size() / 16)
        sensors.push_back({solution.elements->patches[q].centroid, solution.elements->patches[q].normal});
    const std::vector<SensorIrradiance> light = sensor_irradiance(solved->scene, solution, rays, sensors);
    for (const SensorIrradiance& s : light) EXPECT_NEAR(s.total().y, 2.0, 1e-5);
}

TEST(SensorIrradiance, RefusesADirectionThatIsNotAUnitVector) {
    const auto solved = test::solve_scene(make_cornell_box(), Subdivision::uniform, 100.0);
    const Solution solution = test::solution_of(*solved, 100.0);
    const RayScene rays(*solution.elements);
    const std::vector<Sensor> sensors = {{{278, 100, 279}, {0, 0, 0}}};
    EXPECT_THROW(sensor_irradiance(solved->scene, solution, rays, sensors), std::invalid_argument);
}

TEST(SensorIrradiance, IlluminanceAndTheUnobstructedSky) {
    EXPECT_NEAR(illuminance_lux(glm::dvec3(1.0)), 683.0, 1e-9);
    Sky overcast{Sky::Kind::overcast, glm::dvec3(9.0)};
    EXPECT_NEAR(unobstructed_sky_irradiance(overcast).x, 7.0 * std::numbers::pi, 1e-12);
    Sky uniform{Sky::Kind::uniform, glm::dvec3(1.0)};
    EXPECT_NEAR(unobstructed_sky_irradiance(uniform).x, std::numbers::pi, 1e-12);
}

}  // namespace
}  // namespace rad
