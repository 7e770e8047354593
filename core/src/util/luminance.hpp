#pragma once

#include <glm/vec3.hpp>

namespace rad {

// Rec. 709 luminance of linear RGB: where the library weighs brightness, not colour (refinement criteria,
// emitter sampling).
inline double luminance(const glm::dvec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

}  // namespace rad
