#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "rad/scene/texture.hpp"

namespace rad {

// The longest side a texture keeps for the display; a larger image is reduced by a whole factor (texels
// averaged in linear space), so a scene of many photographs stays within memory. Its mean is the full
// image's.
inline constexpr int kMaxDisplayTextureSide = 2048;

// An encoded image (PNG, JPEG, or whatever stb_image decodes) as a Texture named `name`; alpha is ignored.
// Null, with the reason in `why`, when the image cannot be decoded or has more than kMaxTextureTexels.
std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, std::size_t size,
                                              const std::string& name, std::string& why);

}  // namespace rad
