#include "gl/display_pixels.hpp"

#include <glad/gl.h>

#include <cmath>
#include <cstdint>

namespace rad {

namespace {

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

std::vector<glm::vec3> read_display_pixels(int width, int height, int x, int y) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, y, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());

    float value_of_byte[256];
    for (int b = 0; b < 256; ++b) value_of_byte[b] = srgb_decode(static_cast<float>(b) / 255.0f);
    std::vector<glm::vec3> pixels(bytes.size() / 3);
    for (int row = 0; row < height; ++row) {
        const std::size_t source_row = static_cast<std::size_t>(height - 1 - row) *
                                       static_cast<std::size_t>(width);  // OpenGL: bottom first
        for (int column = 0; column < width; ++column) {
            const std::uint8_t* rgb = &bytes[(source_row + static_cast<std::size_t>(column)) * 3];
            pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(column)] =
                glm::vec3(value_of_byte[rgb[0]], value_of_byte[rgb[1]], value_of_byte[rgb[2]]);
        }
    }
    return pixels;
}

}  // namespace rad
