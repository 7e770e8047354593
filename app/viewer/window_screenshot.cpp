#include "viewer/window_screenshot.hpp"

#include <glad/gl.h>

#include <ctime>

#include "gl/display_pixels.hpp"

namespace rad {

Image read_window_image(int width, int height) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    return Image{width, height, read_display_pixels(width, height)};
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
