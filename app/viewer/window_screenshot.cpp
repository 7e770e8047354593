#include "viewer/window_screenshot.hpp"

#include <glad/gl.h>

#include <cmath>
#include <cstdint>
#include <ctime>
#include <vector>

namespace rad {

namespace {

float srgb_decode(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

RadianceImage read_window_image(int width, int height, bool srgb) {
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());

    float value_of_byte[256];
    for (int b = 0; b < 256; ++b) value_of_byte[b] = srgb ? srgb_decode(b / 255.0f) : b / 255.0f;
    RadianceImage image{width, height, std::vector<glm::vec3>(bytes.size() / 3)};
    for (int y = 0; y < height; ++y) {
        const std::size_t source_row =
            static_cast<std::size_t>(height - 1 - y) * width;  // OpenGL: bottom first
        for (int x = 0; x < width; ++x) {
            const std::uint8_t* rgb = &bytes[(source_row + x) * 3];
            image.pixels[static_cast<std::size_t>(y) * width + x] =
                glm::vec3(value_of_byte[rgb[0]], value_of_byte[rgb[1]], value_of_byte[rgb[2]]);
        }
    }
    return image;
}

std::string timestamped_screenshot_path() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char name[64];
    std::strftime(name, sizeof name, "radiosity-%Y%m%d-%H%M%S.png", &local);
    return name;
}

}  // namespace rad
