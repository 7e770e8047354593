#pragma once

#include <cstdint>

namespace rad {

// The sRGB transfer curve of a linear display value, clamped to [0, 1] first (NaN gives 0).
float srgb_encode(float linear);

// The 8-bit sRGB code of a linear display value, round(255 · srgb_encode(linear)): what a PNG pixel and an
// exported vertex colour hold.
std::uint8_t srgb_byte(float linear);

// The linear value of an 8-bit sRGB code (a texel of a PNG or JPEG), from a table.
double srgb_byte_to_linear(std::uint8_t code);

}  // namespace rad
