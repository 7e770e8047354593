#include "viewer/window_screenshot.hpp"

#include <glad/gl.h>

#include <ctime>

#include "gl/display_pixels.hpp"

namespace rad {

Image read_window_image(int width, int height, int x) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    return Image{width, height, read_display_pixels(width, height, x, 0)};
}

std::string timestamped_screenshot_path(const std::filesystem::path& folder) {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stem[64];
    std::strftime(stem, sizeof stem, "radiosity-%Y%m%d-%H%M%S", &local);
    std::filesystem::path path = folder / (std::string(stem) + ".png");
    for (int n = 2; std::filesystem::exists(path); ++n)
        path = folder / (std::string(stem) + "-" + std::to_string(n) + ".png");
    return folder == "." ? path.filename().string() : path.string();
}

}  // namespace rad
