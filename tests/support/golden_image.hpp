#pragma once

#include <string>

namespace rad::test {

// How far an image may stray from its golden one. llvmpipe and GPUs differ in the last bits and at
// multisampled edges, so the test allows a small mean difference and a few pixels that differ more.
struct GoldenTolerance {
    double max_mean_difference = 1.5 / 255.0;  // mean over pixels and channels, in 8-bit sRGB units
    double outlier_difference = 24.0 / 255.0;  // a pixel differing more than this anywhere is an outlier
    double max_outlier_fraction = 0.005;       // at most 0.5 % of the pixels
};

struct GoldenResult {
    bool passed = false;
    std::string message;  // what differed and where the actual and difference images were written
};

// Compares the PNG at `actual_path` with tests/golden/NAME.png. On failure (or when the golden image does
// not exist yet) writes the actual image and a difference image into the build tree's golden-actual/
// folder, from where scripts/promote-golden.sh copies reviewed images into tests/golden/.
GoldenResult compare_with_golden(const std::string& name, const std::string& actual_path,
                                 const GoldenTolerance& tolerance = {});

// The same against the golden image at `golden_path`; the review copies are still named after `name`.
GoldenResult compare_with_image(const std::string& name, const std::string& golden_path,
                                const std::string& actual_path, const GoldenTolerance& tolerance = {});

}  // namespace rad::test
