#include "rad/display/auto_exposure.hpp"

#include <algorithm>
#include <cmath>

namespace rad {

double auto_exposure(const Image& image) {
    double log_sum = 0.0;
    std::size_t lit = 0;
    for (const glm::vec3& p : image.pixels) {
        const double luminance = 0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b;
        // Not-a-number and infinite pixels say nothing about the scene's tones.
        if (!(luminance > 0.0) || !std::isfinite(luminance)) continue;
        log_sum += std::log2(luminance);
        ++lit;
    }
    if (lit == 0) return 0.0;
    const double exposure = std::log2(kAutoExposureKey) - log_sum / static_cast<double>(lit);
    return std::clamp(exposure, -kAutoExposureLimit, kAutoExposureLimit);
}

}  // namespace rad
