#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// The width × height pixels of the bound read framebuffer's read buffer from (x, y) (its lower left corner,
// as OpenGL counts), an 8-bit buffer of sRGB codes (DrawOptions::encode_srgb), decoded to the display values
// clamp(L · 2^exposure), top row first.
std::vector<glm::vec3> read_display_pixels(int width, int height, int x = 0, int y = 0);

}  // namespace rad
