#include "rad/util/srgb.hpp"

#include <array>
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

double srgb_byte_to_linear(std::uint8_t code) {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double v = i / 255.0;
            t[i] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
        }
        return t;
    }();
    return table[code];
}

}  // namespace rad
