#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// The width × height pixels of the bound read framebuffer's read buffer, an 8-bit display buffer, as the
// values the shader wrote (radiance × 2^exposure), top row first: srgb means the buffer holds sRGB codes,
// which are decoded; otherwise it holds the values themselves (clamped to [0, 1] by the buffer).
std::vector<glm::vec3> read_display_pixels(int width, int height, bool srgb);

}  // namespace rad
