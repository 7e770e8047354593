#pragma once

#include <filesystem>
#include <string>

#include "rad/io/image.hpp"

namespace rad {

// The back buffer of the default framebuffer as the radiance scaled by exposure, so write_image(path, image,
// 0) gives the PNG `radiosity render` would (L · 2^exposure, then sRGB): the viewer's shader writes sRGB
// codes, which are decoded. `x` is the left edge of the part read (the 3D view beside the panel). Call after
// drawing, before swap.
Image read_window_image(int width, int height, int x = 0);

// radiosity-YYYYMMDD-HHMMSS.png in `folder` (the working folder), for the screenshot key; where a file of
// that name exists (a second screenshot within the second), radiosity-YYYYMMDD-HHMMSS-2.png, -3, ...
std::string timestamped_screenshot_path(const std::filesystem::path& folder = ".");

}  // namespace rad
