#pragma once

#include "rad/io/image.hpp"

namespace rad {

enum class ErrorChannels {
    // Relative error of the luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709 / sRGB primaries).
    luminance,
    // Mean of the three channels' relative errors, each channel with its own floor.
    rgb,
};

struct ImageErrorOptions {
    int block_size = 8;
    ErrorChannels channels = ErrorChannels::luminance;
    // Values below floor_fraction × the reference image's mean (of the same channel) count as that floor
    // in the denominator, so a near-black reference region neither divides by zero nor dominates the mean.
    double floor_fraction = 0.01;
};

// The mean relative error of `image` against `reference` (the same size) over blocks of block_size ×
// block_size pixels: each block's error is |mean(image) − mean(reference)| / max(mean(reference), floor),
// the means taken over the block's pixels, and blocks are weighted by their pixel count (only the partial
// blocks at the right and bottom edges have fewer). Averaging within a block first lets a noisy reference
// (a path-traced one) converge with the block's 64 pixels' samples instead of each pixel's, and lets an
// image differ a little in where an edge falls (rasterization against box-filtered rays) without
// counting it as error. Luminance by default: one well-conditioned number, and the weak channels of
// saturated surfaces (the Cornell box's red wall has ρ_b = 0.05), where the reference is noisiest
// relative to its value, do not weigh as much as the channels a viewer sees; ErrorChannels::rgb counts
// colour errors too. Throws std::invalid_argument when the sizes differ or an image is empty.
double block_relative_error(const Image& image, const Image& reference,
                            const ImageErrorOptions& options = {});

// What a noisy reference's own noise adds to block_relative_error on its own: the expected error of an
// image that is exactly right, compared with a reference whose pixels have these standard errors (an image of
// the same size, independent from pixel to pixel). Per block it is E|N(0, σ)| = σ √(2/π) over the same
// denominator, σ the standard error of the block's mean; for luminance the channels' errors add as if fully
// correlated (a path carries all three), which bounds σ from above. The true error of an image is then
// about √(error² − noise²). Throws std::invalid_argument when the sizes differ or the image is empty.
double block_relative_noise(const Image& reference, const Image& standard_error,
                            const ImageErrorOptions& options = {});

// The same with blocks of one pixel: the mean over pixels of |image − reference| / max(reference, floor).
// It includes the reference's per-pixel noise, so it is an upper bound of the error against a noisy
// reference rather than an estimate of it.
double pixel_relative_error(const Image& image, const Image& reference,
                            const ImageErrorOptions& options = {});

}  // namespace rad
