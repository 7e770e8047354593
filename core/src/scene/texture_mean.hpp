#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <string>

namespace rad {

// The mean colour of an encoded image (PNG, JPEG, or whatever stb_image decodes), in linear space: the
// texels are sRGB, as glTF's colour textures and OBJ's map_Kd images are, and decoded before they are
// averaged; alpha is ignored. Empty, with the reason in `why`, when the image cannot be decoded or has more
// than kMaxTextureTexels.
std::optional<glm::dvec3> mean_linear_colour(const unsigned char* bytes, std::size_t size, std::string& why);

}  // namespace rad
