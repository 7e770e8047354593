#include "rad/util/srgb.hpp"

#include <cmath>

namespace rad {

float srgb_encode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;  // also NaN
    const float x = linear < 1.0f ? linear : 1.0f;
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

std::uint8_t srgb_byte(float linear) {
    return static_cast<std::uint8_t>(std::lround(255.0f * srgb_encode(linear)));
}

}  // namespace rad
