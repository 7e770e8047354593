#pragma once

namespace rad {

// How bright images are shown: fixed at `ev` (the image shows L · 2^ev), or left to each image's own
// luminance (auto_exposure), the default.
struct Exposure {
    bool automatic = true;
    double ev = 0.0;  // when not automatic

    // `image_ev` is what auto_exposure says of the image at hand.
    double for_image(double image_ev) const { return automatic ? image_ev : ev; }
};

}  // namespace rad
