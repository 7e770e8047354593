#include <gtest/gtest.h>
#include "rad/builtin_scenes.hpp"
TEST(Build, Cornell) { EXPECT_EQ(rad::make_cornell_box().surfaces.size(), 8u); }
