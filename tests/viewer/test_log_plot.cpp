// The residual plot's axes: the decades it spans and their labels.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "viewer/log_plot.hpp"

namespace rad {
namespace {

TEST(LogPlot, SpansWholeDecadesAroundTheValues) {
    const DecadeRange residual = decade_range(-5.1f, -0.66f);  // 7.9e-6 to 0.22
    EXPECT_EQ(residual.low, -6);
    EXPECT_EQ(residual.high, 0);
    const DecadeRange one_value = decade_range(2.0f, 2.0f);  // a single step: one decade, not none
    EXPECT_EQ(one_value.low, 2);
    EXPECT_EQ(one_value.high, 3);
    const DecadeRange bad = decade_range(-std::numeric_limits<float>::infinity(), 1.0f);
    EXPECT_LT(bad.low, bad.high);
}

TEST(LogPlot, LabelsPowersOfTen) {
    EXPECT_EQ(decade_label(0), "1");
    EXPECT_EQ(decade_label(1), "10");
    EXPECT_EQ(decade_label(-3), "1e-03");
    EXPECT_EQ(decade_label(6), "1e+06");
}

}  // namespace
}  // namespace rad
