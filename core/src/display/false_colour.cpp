#include "rad/display/false_colour.hpp"

#include <algorithm>
#include <cmath>

namespace rad {

const std::array<glm::vec3, kFalseColourStops>& false_colour_stops() {
    static const std::array<glm::vec3, kFalseColourStops> stops{
        glm::vec3(0.0f, 0.0f, 0.15f), glm::vec3(0.0f, 0.15f, 1.0f), glm::vec3(0.0f, 0.9f, 1.0f),
        glm::vec3(0.0f, 0.8f, 0.1f),  glm::vec3(1.0f, 0.9f, 0.0f),  glm::vec3(1.0f, 0.05f, 0.0f)};
    return stops;
}

glm::vec3 false_colour(double t) {
    const double x = std::clamp(t, 0.0, 1.0) * (kFalseColourStops - 1);
    const int i = std::min(static_cast<int>(std::floor(x)), kFalseColourStops - 2);
    const float f = static_cast<float>(x - i);
    const auto& stops = false_colour_stops();
    return stops[static_cast<std::size_t>(i)] * (1.0f - f) + stops[static_cast<std::size_t>(i + 1)] * f;
}

FalseColourScale false_colour_scale(double mean, int decades) {
    decades = std::max(decades, 1);
    const double centre = std::isfinite(mean) && mean > 0.0 ? std::log10(mean) : 0.0;
    const double low = std::round(centre - 0.5 * decades);
    return {low, low + decades};
}

}  // namespace rad
