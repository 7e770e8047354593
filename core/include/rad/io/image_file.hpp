#pragma once

#include <string>

#include "rad/io/image.hpp"

namespace rad {

// Writes by the file's extension: .exr (tinyexr) and .pfm hold the radiance as it is; .png applies
// L · 2^exposure and the sRGB curve. The file appears whole or not at all (written to a temporary name in
// the same folder, then renamed). Throws InputError for an unknown extension or a folder we cannot write.
void write_image(const std::string& path, const Image& image, double exposure = 0.0);

// The checks write_image makes before writing, for callers that want to fail before long work.
void check_image_path(const std::string& path);

// Reads .pfm or .png back (PNG as its 8-bit sRGB values / 255, not linearized) for tests and tools.
Image read_image(const std::string& path);

}  // namespace rad
