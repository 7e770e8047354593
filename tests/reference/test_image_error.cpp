// The image error metric: the mean over 8 × 8 blocks of the relative error of the block's mean.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "rad/reference/image_error.hpp"

namespace rad {
namespace {

// A smooth, coloured, strictly positive test image.
Image gradient(int width, int height) {
    Image image{width, height, {}};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.pixels.emplace_back(1.0f + 0.1f * static_cast<float>(x),
                                      0.5f + 0.05f * static_cast<float>(y), 0.25f);
        }
    }
    return image;
}

Image scaled(const Image& image, float s) {
    Image out = image;
    for (glm::vec3& p : out.pixels) p *= s;
    return out;
}

TEST(ImageError, IsZeroAgainstItself) {
    const Image a = gradient(37, 21);
    EXPECT_EQ(block_relative_error(a, a), 0.0);
    EXPECT_EQ(pixel_relative_error(a, a), 0.0);
    EXPECT_EQ(block_relative_error(a, a, {.channels = ErrorChannels::rgb}), 0.0);
}

TEST(ImageError, OfAScaledCopyIsTheScaleError) {
    const Image reference = gradient(40, 24);
    for (const float s : {1.1f, 0.8f}) {
        const Image image = scaled(reference, s);
        EXPECT_NEAR(block_relative_error(image, reference), std::abs(s - 1.0f), 1e-6) << s;
        EXPECT_NEAR(pixel_relative_error(image, reference), std::abs(s - 1.0f), 1e-6) << s;
        EXPECT_NEAR(block_relative_error(image, reference, {.channels = ErrorChannels::rgb}),
                    std::abs(s - 1.0f), 1e-6)
            << s;
    }
}

// Noise that averages out within a block costs the pixel error but not the block error.
TEST(ImageError, BlocksAverageOutPixelNoise) {
    const Image flat = filled_image(16, 16, glm::vec3(1.0f));
    Image checker = flat;
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) checker.at(x, y) *= (x + y) % 2 ? 1.2f : 0.8f;
    }
    EXPECT_NEAR(block_relative_error(checker, flat), 0.0, 1e-6);
    EXPECT_NEAR(pixel_relative_error(checker, flat), 0.2, 1e-6);
}

// A block whose reference is black counts against the floor, a share of the reference's mean, so it adds a
// bounded amount instead of infinity; black against black is no error.
TEST(ImageError, BlackReferenceBlocksUseTheFloor) {
    Image reference = filled_image(16, 8);
    // The left 8 × 8 block is lit (luminance 1), the right one black.
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) reference.at(x, y) = glm::vec3(1.0f);
    }
    EXPECT_EQ(block_relative_error(reference, reference), 0.0);
    Image image = reference;
    for (int y = 0; y < 8; ++y) {
        for (int x = 8; x < 16; ++x) image.at(x, y) = glm::vec3(0.001f);
    }
    // The reference's mean luminance is 0.5, so the floor is 0.005 and the dark block's error 0.001 / 0.005.
    const double expected = 0.5 * (0.0 + 0.001 / 0.005);
    EXPECT_NEAR(block_relative_error(image, reference), expected, 1e-5);
    ImageErrorOptions no_floor;
    no_floor.floor_fraction = 0.0;
    // Without a floor, a black reference block counts as no error rather than infinity.
    EXPECT_EQ(block_relative_error(image, reference, no_floor), 0.0);
}

// Partial blocks at the right and bottom edges weigh by their pixels: a 9 × 9 image is one 8 × 8 block and
// three thin ones; only the corner pixel is wrong, by 100 %.
TEST(ImageError, EdgeBlocksWeighByTheirPixels) {
    const Image reference = filled_image(9, 9, glm::vec3(1.0f));
    Image image = reference;
    image.pixels.back() = glm::vec3(2.0f);
    EXPECT_NEAR(block_relative_error(image, reference), 1.0 / 81.0, 1e-6);
}

// A right image against a reference with Gaussian pixel noise of known standard error: its block error is
// what block_relative_noise predicts, within the sampling spread of 1024 blocks (about 2.5 %), and twice the
// noise gives twice the error.
TEST(ImageError, ReferenceNoiseAloneIsPredicted) {
    const int size = 256;
    const glm::vec3 truth(2.0f, 1.0f, 0.5f);
    const Image right = filled_image(size, size, truth);
    std::mt19937_64 random(5);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    for (float sigma : {0.25f, 0.5f}) {
        Image noisy = right;
        // One draw scales all three channels, as one path's light does.
        for (glm::vec3& p : noisy.pixels) p *= 1.0f + sigma * normal(random);
        const Image standard_error = filled_image(size, size, sigma * truth);
        const double predicted = block_relative_noise(noisy, standard_error);
        // σ of a block's mean luminance relative to its value: σ / 8; times √(2/π).
        EXPECT_NEAR(predicted, sigma / 8 * std::sqrt(2 / std::numbers::pi), 0.02 * predicted);
        EXPECT_NEAR(block_relative_error(right, noisy) / predicted, 1.0, 0.08) << "σ " << sigma;
    }
    EXPECT_THROW(block_relative_noise(right, filled_image(3, 1)), std::invalid_argument);
    EXPECT_THROW(block_relative_noise(right, filled_image(size / 2, size * 2)), std::invalid_argument);
}

TEST(ImageError, RejectsImagesOfDifferentSizes) {
    const Image a = gradient(8, 8), b = gradient(8, 9);
    EXPECT_THROW(block_relative_error(a, b), std::invalid_argument);
    EXPECT_THROW(block_relative_error(Image{}, Image{}), std::invalid_argument);
}

}  // namespace
}  // namespace rad
