#include "scene/texture_mean.hpp"

#include <stb_image.h>

#include <array>
#include <climits>
#include <cmath>
#include <memory>

#include "scene/scene_limits.hpp"

namespace rad {

namespace {

double srgb_to_linear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

const std::array<double, 256>& linear_of_byte() {
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgb_to_linear(i / 255.0);
        return t;
    }();
    return table;
}

}  // namespace

std::optional<glm::dvec3> mean_linear_colour(const unsigned char* bytes, std::size_t size, std::string& why) {
    if (size == 0 || size > INT_MAX) {
        why = "the image is empty or too large to decode";
        return std::nullopt;
    }
    int width = 0, height = 0, channels = 0;
    // The header first: the texel count decides whether decoding it is worth its memory.
    if (!stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels)) {
        why = std::string("stb_image cannot decode it (") + stbi_failure_reason() + ")";
        return std::nullopt;
    }
    if (width <= 0 || height <= 0 ||
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) > kMaxTextureTexels) {
        why = "it has " + std::to_string(width) + " × " + std::to_string(height) +
              " texels, more than the limit of " + std::to_string(kMaxTextureTexels);
        return std::nullopt;
    }
    const std::unique_ptr<unsigned char, decltype(&stbi_image_free)> texels(
        stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, 3),
        &stbi_image_free);
    if (!texels) {
        why = std::string("stb_image cannot decode it (") + stbi_failure_reason() + ")";
        return std::nullopt;
    }
    const auto& linear = linear_of_byte();
    const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) sum[c] += linear[texels.get()[3 * i + c]];
    }
    return sum / static_cast<double>(count);
}

}  // namespace rad
