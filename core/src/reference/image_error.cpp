#include "rad/reference/image_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace rad {

namespace {

constexpr int kMaxChannels = 3;

// The values compared, per pixel: one (luminance) or three (RGB) channels.
struct Channels {
    int count = 1;
    std::array<double, kMaxChannels> of(const glm::vec3& c) const {
        if (count == 1) return {0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b, 0.0, 0.0};
        return {c.r, c.g, c.b};
    }
};

void check_sizes(const Image& image, const Image& reference, const ImageErrorOptions& options) {
    if (reference.width <= 0 || reference.height <= 0 || reference.pixels.size() != reference.pixel_count()) {
        throw std::invalid_argument("image error: the reference image is empty or its size is inconsistent");
    }
    if (image.width != reference.width || image.height != reference.height ||
        image.pixels.size() != reference.pixels.size()) {
        throw std::invalid_argument("image error: the images differ in size");
    }
    if (options.block_size <= 0 || !(options.floor_fraction >= 0.0)) {
        throw std::invalid_argument("image error: block size must be positive, floor fraction not negative");
    }
}

std::array<double, kMaxChannels> floors(const Image& reference, const Channels& channels, double fraction) {
    std::array<double, kMaxChannels> sum{};
    for (const glm::vec3& p : reference.pixels) {
        const auto v = channels.of(p);
        for (int c = 0; c < channels.count; ++c) sum[c] += v[c];
    }
    std::array<double, kMaxChannels> floor{};
    for (int c = 0; c < channels.count; ++c) {
        floor[c] = fraction * sum[c] / static_cast<double>(reference.pixels.size());
    }
    return floor;
}

// Calls visit(index) for each pixel of the block whose top-left pixel is (x0, y0) and returns the block's
// pixel count (fewer at the right and bottom edges).
template <typename Visit>
double visit_block(const Image& reference, int x0, int y0, int size, Visit visit) {
    const int x1 = std::min(x0 + size, reference.width), y1 = std::min(y0 + size, reference.height);
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            visit(static_cast<std::size_t>(y) * static_cast<std::size_t>(reference.width) +
                  static_cast<std::size_t>(x));
        }
    }
    return static_cast<double>(x1 - x0) * static_cast<double>(y1 - y0);
}

// The relative error of one block whose top-left pixel is (x0, y0), averaged over the channels.
double block_error(const Image& image, const Image& reference, int x0, int y0, int size,
                   const Channels& channels, const std::array<double, kMaxChannels>& floor) {
    std::array<double, kMaxChannels> a{}, b{};
    const double n = visit_block(reference, x0, y0, size, [&](std::size_t index) {
        const auto va = channels.of(image.pixels[index]), vb = channels.of(reference.pixels[index]);
        for (int c = 0; c < channels.count; ++c) {
            a[c] += va[c];
            b[c] += vb[c];
        }
    });
    double error = 0.0;
    for (int c = 0; c < channels.count; ++c) {
        const double denominator = std::max(b[c] / n, floor[c]);
        if (denominator > 0.0) error += std::abs(a[c] - b[c]) / n / denominator;
    }
    return error / channels.count;
}

// The expected relative error that the reference's noise alone gives one block (see block_relative_noise).
double block_noise(const Image& reference, const Image& standard_error, int x0, int y0, int size,
                   const Channels& channels, const std::array<double, kMaxChannels>& floor) {
    std::array<double, kMaxChannels> mean{}, variance{};
    const double n = visit_block(reference, x0, y0, size, [&](std::size_t index) {
        const auto value = channels.of(reference.pixels[index]);
        // Channels.of is linear with non-negative weights: applied to the standard errors it adds them as
        // fully correlated.
        const auto error = channels.of(standard_error.pixels[index]);
        for (int c = 0; c < channels.count; ++c) {
            mean[c] += value[c];
            variance[c] += error[c] * error[c];
        }
    });
    const double mean_absolute_normal = std::sqrt(2.0 / std::numbers::pi);
    double noise = 0.0;
    for (int c = 0; c < channels.count; ++c) {
        const double denominator = std::max(mean[c] / n, floor[c]);
        if (denominator > 0.0) noise += mean_absolute_normal * std::sqrt(variance[c]) / n / denominator;
    }
    return noise / channels.count;
}

// The pixel-weighted mean over blocks of block_value(x0, y0).
template <typename BlockValue>
double mean_over_blocks(const Image& reference, int size, BlockValue block_value) {
    double weighted = 0.0;
    for (int y0 = 0; y0 < reference.height; y0 += size) {
        for (int x0 = 0; x0 < reference.width; x0 += size) {
            const double pixels = static_cast<double>(std::min(size, reference.width - x0)) *
                                  static_cast<double>(std::min(size, reference.height - y0));
            weighted += pixels * block_value(x0, y0);
        }
    }
    return weighted / static_cast<double>(reference.pixels.size());
}

}  // namespace

double block_relative_noise(const Image& reference, const Image& standard_error,
                            const ImageErrorOptions& options) {
    check_sizes(reference, reference, options);
    if (standard_error.width != reference.width || standard_error.height != reference.height ||
        standard_error.pixels.size() != reference.pixels.size()) {
        throw std::invalid_argument("image noise: one standard error per pixel is needed");
    }
    const Channels channels{options.channels == ErrorChannels::rgb ? 3 : 1};
    const auto floor = floors(reference, channels, options.floor_fraction);
    return mean_over_blocks(reference, options.block_size, [&](int x0, int y0) {
        return block_noise(reference, standard_error, x0, y0, options.block_size, channels, floor);
    });
}

double block_relative_error(const Image& image, const Image& reference, const ImageErrorOptions& options) {
    check_sizes(image, reference, options);
    const Channels channels{options.channels == ErrorChannels::rgb ? 3 : 1};
    const auto floor = floors(reference, channels, options.floor_fraction);
    return mean_over_blocks(reference, options.block_size, [&](int x0, int y0) {
        return block_error(image, reference, x0, y0, options.block_size, channels, floor);
    });
}

double pixel_relative_error(const Image& image, const Image& reference, const ImageErrorOptions& options) {
    ImageErrorOptions per_pixel = options;
    per_pixel.block_size = 1;
    return block_relative_error(image, reference, per_pixel);
}

}  // namespace rad
