// Auto exposure: the EV that maps an image's log-average luminance to 0.18 grey, blind to black background
// pixels and to non-finite ones, barely moved by a light in view, within ±100 EV.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rad/display/auto_exposure.hpp"

namespace rad {
namespace {

TEST(AutoExposure, AUniformImageLandsOnTheKey) {
    for (const float l : {1e-6f, 0.05f, 2.0f / 3.14159265f, 17.0f, 1e6f}) {
        SCOPED_TRACE(l);
        const double ev = auto_exposure(filled_image(8, 4, glm::vec3(l)));
        EXPECT_NEAR(static_cast<double>(l) * std::exp2(ev), kAutoExposureKey, 1e-6 * kAutoExposureKey);
    }
}

// The geometric mean of a two-tone image, and the same EV for the image 2^k times brighter, k EV lower.
TEST(AutoExposure, ItIsTheGeometricMeanAndFollowsTheLightsScale) {
    Image image = filled_image(2, 1);
    image.at(0, 0) = glm::vec3(0.01f);
    image.at(1, 0) = glm::vec3(1.0f);
    EXPECT_NEAR(auto_exposure(image), std::log2(0.18 / 0.1), 1e-6);
    Image brighter = image;
    for (glm::vec3& p : brighter.pixels) p *= 1024.0f;
    EXPECT_NEAR(auto_exposure(brighter), auto_exposure(image) - 10.0, 1e-6);
}

// Luminance by Rec. 709's weights: a pure green pixel counts 0.7152 of its value.
TEST(AutoExposure, ColoursCountByTheirLuminance) {
    EXPECT_NEAR(auto_exposure(filled_image(1, 1, glm::vec3(0.0f, 1.0f, 0.0f))), std::log2(0.18 / 0.7152),
                1e-6);
}

TEST(AutoExposure, BlackAndNonFinitePixelsAreLeftOut) {
    Image image = filled_image(4, 4);  // black: the background
    EXPECT_EQ(auto_exposure(image), 0.0);
    image.at(1, 1) = glm::vec3(0.5f);
    image.at(2, 2) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    image.at(3, 3) = glm::vec3(std::numeric_limits<float>::infinity());
    EXPECT_NEAR(auto_exposure(image), std::log2(0.18 / 0.5), 1e-6);
}

// A light in view: 4 pixels of L = 1e4 among 1024 of walls at 0.1 move the exposure by 4/1024 of
// log2(1e5), 0.065 EV, where an average of the values themselves would darken the walls by 5 EV.
TEST(AutoExposure, ALightInViewBarelyMovesIt) {
    Image image = filled_image(32, 32, glm::vec3(0.1f));
    const double walls = auto_exposure(image);
    for (int k = 0; k < 4; ++k) image.at(k, 0) = glm::vec3(1e4f);
    EXPECT_NEAR(walls - auto_exposure(image), 4.0 / 1024.0 * std::log2(1e5), 1e-4);
}

TEST(AutoExposure, ItStaysWithinTheLimit) {
    EXPECT_EQ(auto_exposure(filled_image(1, 1, glm::vec3(1e-38f))), kAutoExposureLimit);
    EXPECT_EQ(auto_exposure(filled_image(1, 1, glm::vec3(3e38f))), -kAutoExposureLimit);
}

}  // namespace
}  // namespace rad
