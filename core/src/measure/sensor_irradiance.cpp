#include "rad/measure/sensor_irradiance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "light/point_direct_light.hpp"
#include "rad/display/false_colour.hpp"
#include "rad/display/solution_display.hpp"
#include "ray/ray_offset.hpp"
#include "sampling/edge_strata.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

// Keys of the sensors' random streams, apart from every other pass's.
constexpr std::uint64_t kSensorSkyKey = 0x5e45'0a5c'0000'0001ull;
constexpr std::uint64_t kSensorGatherKey = 0x5e45'0a5c'0000'0002ull;
constexpr std::uint64_t kSensorDirectKey = 0x5e45'0a5c'0000'0003ull;
// A split stratum is integrated again as kSplit x kSplit sub-strata.
constexpr int kSplit = 4;

struct Origin {
    glm::dvec3 point;
    Frame frame;
};

Ray ray_from(const Origin& o, const glm::dvec2& u) {
    return Ray{o.point, 0.0f, o.frame.to_world(cosine_direction(u)), std::numeric_limits<float>::infinity()};
}

// The mean sky radiance over the square [corner, corner + size]² of the cosine-mapped unit square, as
// side x side strata of one ray each. A stratum whose neighbours disagree on whether they reach the sky (the
// sky's edge crosses it) is integrated again, kSplit x kSplit finer, while `splits` last; the choice looks
// only at the neighbours' rays, so a stratum's own ray, where kept, stays an unbiased sample.
glm::dvec3 mean_sky(const Sky& sky, const RayScene& scene, const Origin& o, const glm::dvec2& corner,
                    double size, int side, int splits, RandomStream& random) {
    const auto n = static_cast<std::size_t>(side * side);
    const double cell = size / side;
    std::vector<Ray> rays(n);
    std::vector<RayHit> hits(n);
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec2 u = corner + cell * glm::dvec2(static_cast<double>(k % side) + random.uniform(),
                                                        static_cast<double>(k / side) + random.uniform());
        rays[k] = ray_from(o, u);
    }
    scene.intersect(rays, hits);
    const auto open = [&](int x, int y) {
        return hits[static_cast<std::size_t>(y * side + x)].patch == RayHit::kMissed;
    };
    glm::dvec3 sum(0.0);
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            if (splits > 0 && neighbours_disagree(x, y, side, open)) {
                sum += mean_sky(sky, scene, o, corner + cell * glm::dvec2(x, y), cell, kSplit, splits - 1,
                                random);
                continue;
            }
            if (open(x, y))
                sum +=
                    sky.radiance_from(glm::normalize(rays[static_cast<std::size_t>(y * side + x)].direction));
        }
    }
    return sum / static_cast<double>(n);
}

// The sun's irradiance on the sensor where one shadow ray toward it is clear.
glm::dvec3 sun_at(const Sun& sun, const RayScene& scene, const Origin& o) {
    const double cosine = glm::dot(o.frame.normal, sun.direction);
    if (!(cosine > 0.0)) return glm::dvec3(0.0);
    const Ray ray{o.point, 0.0f, sun.direction, std::numeric_limits<float>::infinity()};
    std::uint8_t blocked = 0;
    scene.occluded(std::span(&ray, 1), std::span(&blocked, 1));
    return blocked ? glm::dvec3(0.0) : cosine * sun.irradiance;
}

// The solution's light reflected toward the sensor: Σ (B − source) of the elements its stratified cosine rays
// meet from the front, over the rays.
glm::dvec3 reflected_at(const RayScene& scene, const Origin& o, std::span<const glm::dvec3> radiosity,
                        std::span<const glm::dvec3> source, RandomStream& random) {
    std::vector<glm::dvec2> strata(kSensorGatherRays);
    stratified_square(random, strata, false);
    std::vector<Ray> rays(strata.size());
    std::vector<RayHit> hits(strata.size());
    for (std::size_t k = 0; k < strata.size(); ++k) rays[k] = ray_from(o, strata[k]);
    scene.intersect(rays, hits);
    glm::dvec3 sum(0.0);
    for (const RayHit& hit : hits)
        if (hit.patch != RayHit::kMissed && hit.patch != RayHit::kBackFace)
            sum += radiosity[hit.patch] - source[hit.patch];
    return sum / static_cast<double>(hits.size());
}

void check_sensors(std::span<const Sensor> sensors) {
    for (std::size_t k = 0; k < sensors.size(); ++k) {
        const Sensor& s = sensors[k];
        const bool finite = std::isfinite(s.point.x) && std::isfinite(s.point.y) && std::isfinite(s.point.z);
        if (!finite || !(std::abs(glm::length(s.direction) - 1.0) < 1e-6))
            throw std::invalid_argument("sensor " + std::to_string(k) +
                                        ": the point is not finite or the direction not a unit vector");
    }
}

}  // namespace

std::vector<SensorIrradiance> sensor_irradiance(const Scene& scene, const Solution& solution,
                                                const RayScene& element_rays, std::span<const Sensor> sensors,
                                                std::uint64_t seed, Progress* progress) {
    check_solution_fits(scene, solution);
    check_sensors(sensors);
    const PatchMesh& elements = *solution.elements;
    const double offset = ray_offset(elements);
    std::vector<glm::dvec3> points(sensors.size()), normals(sensors.size());
    for (std::size_t k = 0; k < sensors.size(); ++k) {
        points[k] = sensors[k].point + offset * sensors[k].direction;
        normals[k] = sensors[k].direction;
    }
    // The emitters' light is traced where the display traces it; else (a furnace) it is the elements'.
    std::vector<glm::dvec3> source = emitted_radiosity(scene, elements);
    const bool traced = draws_vertex_direct_light(elements, source);
    if (!traced) source.assign(source.size(), glm::dvec3(0.0));
    std::vector<SensorIrradiance> out(sensors.size());
    if (traced) {
        const std::vector<glm::dvec3> direct =
            direct_irradiance_at(elements, element_rays, source, points, normals, seed ^ kSensorDirectKey);
        for (std::size_t k = 0; k < out.size(); ++k) out[k].emitters = direct[k];
    }
    if (progress) progress->begin("light at the sensors", sensors.size());
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, sensors.size(), 4),
        [&](const tbb::blocked_range<std::size_t>& range) {
            if (progress && progress->cancelled()) throw Cancelled{};
            for (std::size_t k = range.begin(); k != range.end(); ++k) {
                const Origin o{points[k], frame_around(normals[k])};
                if (scene.sky.present()) {
                    RandomStream random(seed ^ kSensorSkyKey, k);
                    out[k].sky = std::numbers::pi * mean_sky(scene.sky, element_rays, o, glm::dvec2(0.0), 1.0,
                                                             kSensorSkyStrataSide, kSensorSkySplits, random);
                }
                if (scene.sun.present()) out[k].sun = sun_at(scene.sun, element_rays, o);
                RandomStream random(seed ^ kSensorGatherKey, k);
                out[k].reflected = reflected_at(element_rays, o, solution.radiosity, source, random);
            }
            if (progress) progress->advance(range.size());
        });
    return out;
}

double illuminance_lux(const glm::dvec3& irradiance) {
    return kLuminousEfficacy * rec709_luminance(irradiance);
}

glm::dvec3 unobstructed_sky_irradiance(const Sky& sky) {
    switch (sky.kind) {
        case Sky::Kind::uniform:
            return std::numbers::pi * sky.radiance;
        case Sky::Kind::overcast:
            return 7.0 * std::numbers::pi / 9.0 * sky.radiance;
        case Sky::Kind::none:
            break;
    }
    return glm::dvec3(0.0);
}

}  // namespace rad
