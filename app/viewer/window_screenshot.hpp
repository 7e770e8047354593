#pragma once

#include <string>

#include "image_io.hpp"

namespace rad {

// The back buffer of the default framebuffer as the radiance scaled by exposure, so write_image(path, image,
// 0) gives the PNG `radiosity render` would (L · 2^exposure, then sRGB). srgb: the framebuffer stores sRGB
// codes (they are decoded); otherwise it holds the scaled radiance itself. Call after drawing, before swap.
RadianceImage read_window_image(int width, int height, bool srgb);

// radiosity-YYYYMMDD-HHMMSS.png in the working folder, for the screenshot key.
std::string timestamped_screenshot_path();

}  // namespace rad
