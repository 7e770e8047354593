#pragma once

#include "rad/io/image.hpp"

namespace rad {

// The grey a photograph's average lands on: auto exposure maps an image's log-average luminance here.
inline constexpr double kAutoExposureKey = 0.18;

// Exposures beyond this (in EV) are never chosen, so 2^exposure stays a finite float.
inline constexpr double kAutoExposureLimit = 100.0;

// The exposure (EV, the image shows L · 2^EV) that maps the geometric mean of the lit pixels' luminance
// (Rec. 709 weights; black pixels, the background, left out) to kAutoExposureKey: the rule of a camera's
// averaging meter (Reinhard et al. 2002). A few very bright pixels (a light in view) barely move it, so the
// walls a light shines on keep their tones. 0 for an image with no lit pixel.
double auto_exposure(const Image& image);

}  // namespace rad
