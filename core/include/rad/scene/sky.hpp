#pragma once

#include <glm/vec3.hpp>

namespace rad {

// Light from outside the scene. The sky is an emitter at infinity: every ray that leaves the scene meets
// it. Up is +y, as in OBJ and glTF.
struct Sky {
    enum class Kind {
        none,
        uniform,   // radiance in every direction, below the horizon too (a scene without a ground is lit
                   // from below as well)
        overcast,  // the CIE standard overcast sky: L(θ) = Lz (1 + 2 cos θ) / 3 above the horizon, θ from
                   // the zenith, and nothing below it (the scene's own ground, if any, is there)
    };
    Kind kind = Kind::none;
    glm::dvec3 radiance{0.0};  // uniform: L per channel; overcast: Lz, the zenith's

    bool present() const;
    // The radiance that arrives from the sky along `toward`, a unit direction pointing out of the scene.
    glm::dvec3 radiance_from(const glm::dvec3& toward) const;
};

// A distant light from one direction, tested with shadow rays.
struct Sun {
    glm::dvec3 direction{0.0, 1.0, 0.0};  // unit, from the scene toward the sun
    glm::dvec3 irradiance{0.0};           // per channel, on a plane facing the sun

    bool present() const;
};

}  // namespace rad
