#pragma once

#include <cstdint>

namespace rad {

// The sRGB transfer curve of a linear display value, clamped to [0, 1] first (NaN gives 0).
float srgb_encode(float linear);

// The 8-bit sRGB code of a linear display value, round(255 · srgb_encode(linear)): what a PNG pixel and an
// exported vertex colour hold.
std::uint8_t srgb_byte(float linear);

}  // namespace rad
