#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

namespace rad {

// An image of linear radiance L (scene units), width × height, top row first: pixel (0, 0) is the top left.
// The one image type: what the renderer reads back, the path tracer estimates, the image-error measures
// compare and image files hold. An aggregate, so Image{width, height, pixels} builds one.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels;  // row by row, width × height

    // width × height, what pixels.size() should be.
    std::size_t pixel_count() const {
        return static_cast<std::size_t>(width < 0 ? 0 : width) *
               static_cast<std::size_t>(height < 0 ? 0 : height);
    }
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
    }
    // Unchecked, as pixels[index]: the callers loop over the image's own size.
    glm::vec3& at(int x, int y) { return pixels[index(x, y)]; }
    const glm::vec3& at(int x, int y) const { return pixels[index(x, y)]; }
};

// A width × height image of one value (black by default).
inline Image filled_image(int width, int height, glm::vec3 value = glm::vec3(0.0f)) {
    Image image{width, height, {}};
    image.pixels.assign(image.pixel_count(), value);
    return image;
}

}  // namespace rad
