#pragma once

#include <cstddef>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// How the render thread draws what the worker computed; changed from the panel and the keyboard.
struct ViewSettings {
    double exposure = 0.0;      // the image shows L · 2^exposure
    bool auto_exposure = true;  // exposure metered from the view (auto_exposure)
    bool outline = false;       // patch edges over the patches
    bool bounce_only = false;   // one bounce alone instead of the cumulative solution
    bool newest_bounce = true;  // bounce_only shows the newest step's light, else `bounce`'s
    std::size_t bounce = 0;
    ColourMode mode = ColourMode::smooth;
    bool orbit = false;
    // Luminance in false colours with a legend, over this many decades around the view's log-average.
    bool false_colour = false;
    int false_colour_decades = 4;
    // Views kept for coming back to (keys 1 to 9), and written as a cameras file `render --cameras` takes.
    std::vector<Camera> bookmarks;
};

}  // namespace rad
