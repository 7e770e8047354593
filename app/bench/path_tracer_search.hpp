#pragma once

#include <functional>

namespace rad {

// One path-traced image: its paths per pixel, time and image error.
struct PathTracerSample {
    int spp = 0;
    double seconds = 0.0;
    double error = 0.0;
};

struct PathTracerSearch {
    bool found = false;        // false: not reached within max_spp
    PathTracerSample above;    // the last image above the target error (spp 0: none was)
    PathTracerSample reached;  // the first image at or below it (or the last tried, when not found)
    double spp = 0.0;          // interpolated paths per pixel at the target error
    double seconds = 0.0;      // the time of an image at that many paths per pixel
};

// The paths per pixel the path tracer needs to reach `target` image error. Images are measured at powers of
// two from `start`, up until one reaches the target, or down while they still reach it, so that two
// neighbours bracket it; between them spp is interpolated in log-log (an unbiased estimate's error falls as
// spp^-1/2, a little slower against a noisy reference), and time is taken in proportion to spp. Reporting
// the power of two that first reaches the target would overstate the path tracer's cost by up to 2 times.
PathTracerSearch find_path_tracer_spp(const std::function<PathTracerSample(int spp)>& measure, double target,
                                      int start, int max_spp);

}  // namespace rad
