// The false-colour view's map and scale: the stops at the ends, linear between them, and a scale of whole
// decades around the view's mean luminance.
#include <gtest/gtest.h>

#include "rad/display/false_colour.hpp"

namespace rad {
namespace {

TEST(FalseColour, TheMapRunsThroughItsStops) {
    const auto& stops = false_colour_stops();
    EXPECT_EQ(false_colour(0.0), stops.front());
    EXPECT_EQ(false_colour(1.0), stops.back());
    EXPECT_EQ(false_colour(-3.0), stops.front());
    EXPECT_EQ(false_colour(7.0), stops.back());
    // Halfway: halfway between the third and the fourth of six stops.
    const glm::vec3 half = false_colour(0.5);
    const glm::vec3 expected = 0.5f * (stops[2] + stops[3]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(half[c], expected[c], 1e-6f);
    EXPECT_NEAR(false_colour(0.2).g, stops[1].g, 1e-6f);  // on a stop exactly
}

TEST(FalseColour, TheScaleIsWholeDecadesAroundTheMean) {
    const FalseColourScale lamp = false_colour_scale(8500.0, 4);  // log10 3.93
    EXPECT_DOUBLE_EQ(lamp.log10_low, 2.0);
    EXPECT_DOUBLE_EQ(lamp.log10_high, 6.0);
    const FalseColourScale dim = false_colour_scale(0.02, 2);  // log10 -1.7
    EXPECT_DOUBLE_EQ(dim.log10_low, -3.0);
    EXPECT_DOUBLE_EQ(dim.log10_high, -1.0);
    const FalseColourScale dark = false_colour_scale(0.0, 4);  // a black view: around 1 cd/m²
    EXPECT_DOUBLE_EQ(dark.log10_low, -2.0);
    EXPECT_DOUBLE_EQ(dark.log10_high, 2.0);
}

}  // namespace
}  // namespace rad
