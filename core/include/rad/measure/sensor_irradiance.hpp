#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solution.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// A point where light is measured and the unit direction its sensor faces (Radiance's rtrace -I: the
// irradiance on a small plane at the point, facing that way).
struct Sensor {
    glm::dvec3 point{0.0};
    glm::dvec3 direction{0.0, 1.0, 0.0};
};

// The irradiance a sensor receives (W/m² per channel, the scene's units), by where it comes from.
struct SensorIrradiance {
    glm::dvec3 emitters{0.0};   // the emitters' light, traced to them
    glm::dvec3 sky{0.0};        // the sky's, through whatever opens onto it
    glm::dvec3 sun{0.0};        // the sun's, where its shadow ray is clear
    glm::dvec3 reflected{0.0};  // every surface's reflected light, from the solution's elements
    glm::dvec3 total() const { return emitters + sky + sun + reflected; }
};

// Cosine-weighted strata of the sky per sensor (side x side), and how many times a stratum the sky's edge
// crosses (a window's frame) is split 4 x 4 again, finer each time.
inline constexpr int kSensorSkyStrataSide = 64;
inline constexpr int kSensorSkySplits = 4;
// Cosine-weighted rays per sensor that gather the surfaces' reflected light from the solution.
inline constexpr int kSensorGatherRays = 4096;

// What each sensor receives in `scene` lit as `solution` says, without form factors or a solve: the
// emitters' light traced exactly at the point (the display's vertex estimator: exact unoccluded factors where
// every shadow ray is clear, power-drawn shadow rays in a penumbra), the sky by stratified rays whose strata
// on the sky's edge are split again (kSensorSkySplits times), the sun by one shadow ray, and the rest from
// the solution's elements met by kSensorGatherRays stratified rays (their radiosity less what they emit
// themselves where the emitters are traced). `element_rays` are over the solution's elements. A sensor's
// rays leave from its point moved by the ray offset along its direction, so a sensor on a surface sees what
// is in front of it. Deterministic for a seed. Throws std::invalid_argument when the solution does not fit
// the scene or a direction is not a unit vector, and Cancelled when `progress` is cancelled.
std::vector<SensorIrradiance> sensor_irradiance(const Scene& scene, const Solution& solution,
                                                const RayScene& element_rays, std::span<const Sensor> sensors,
                                                std::uint64_t seed = 1, Progress* progress = nullptr);

// Illuminance in lux of an irradiance in W/m² per channel: 683 lm/W times its Rec. 709 luminance.
double illuminance_lux(const glm::dvec3& irradiance);

// The illuminance (W/m² per channel) the sky alone gives an unobstructed horizontal plane: π L for a uniform
// sky (its upper half), 7π/9 Lz for the CIE overcast sky; 0 without a sky. A daylight factor divides by it.
glm::dvec3 unobstructed_sky_irradiance(const Sky& sky);

}  // namespace rad
