#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace rad {

// A colour texture as the display draws it: 8-bit sRGB texels, rows from the image's top. Texture
// coordinates follow glTF's convention (v = 0 on the first row; OBJ's v is flipped when it is read) and
// repeat outside [0, 1]. `mean` is the linear mean of the image as decoded, before any reduction for the
// display; a textured material's reflectance is its factor times that mean.
struct Texture {
    std::string name;  // as the scene file names it, for messages
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> srgb;  // RGB, width × height × 3
    glm::dvec3 mean{0.0};

    // The linear colour at (u, v), filtered bilinearly between texel centres, as OpenGL samples it.
    glm::dvec3 linear_at(const glm::dvec2& uv) const;
};

// What a texel of `texture` holds as albedo on a material of mean reflectance `reflectance`: the texel's
// linear colour times reflectance / mean, per channel (0 where the mean is 0), so the albedo's mean over the
// image is the material's reflectance.
glm::dvec3 albedo_scale(const Texture& texture, const glm::dvec3& reflectance);

}  // namespace rad
