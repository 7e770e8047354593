#pragma once

#include <array>
#include <glm/vec3.hpp>

namespace rad {

// The false-colour view's convention: a scene's emitted radiance (MTL Ke) is read as W/(m² sr) per channel,
// each watt counted at the eye's peak sensitivity, so luminance is 683 lm/W times the Rec. 709 luminance of
// the RGB radiance, in cd/m² (nits). Radiance does not depend on the scene's length unit (results do not
// depend on scale), so neither does this.
inline constexpr double kLuminousEfficacy = 683.0;  // lm/W

// Rec. 709 luminance of a linear RGB value.
inline double rec709_luminance(const glm::dvec3& rgb) {
    return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b;
}

// The colour map, evenly spaced from the bottom of the scale to its top: dark blue, blue, cyan, green,
// yellow, red (linear RGB). The shader and the legend both draw these.
inline constexpr int kFalseColourStops = 6;
const std::array<glm::vec3, kFalseColourStops>& false_colour_stops();

// The map at t in [0, 1] (clamped), interpolated linearly between the stops.
glm::vec3 false_colour(double t);

// What the false colours span: luminance from 10^log10_low to 10^log10_high cd/m², logarithmically.
struct FalseColourScale {
    double log10_low = -1.0;
    double log10_high = 3.0;
};

// A scale of `decades` centred, in decades, on the luminance `mean` (cd/m²; the view's log-average),
// rounded to whole decades so the legend reads in powers of ten.
FalseColourScale false_colour_scale(double mean, int decades = 4);

}  // namespace rad
