// The bench's search for the paths per pixel the path tracer needs to reach an image error, on a model
// whose error is exactly c / √spp: the answer is c² / target², wherever the search starts.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "bench/path_tracer_search.hpp"

namespace rad {
namespace {

struct Model {
    double c = 0.16;               // error at 1 spp
    double seconds_per_spp = 0.5;  // time grows with spp
    std::vector<int> measured;

    PathTracerSample operator()(int spp) {
        measured.push_back(spp);
        return {spp, seconds_per_spp * spp, c / std::sqrt(static_cast<double>(spp))};
    }
};

TEST(PathTracerSearch, InterpolatesBetweenThePowersOfTwoThatBracketTheTarget) {
    for (int start : {1, 8, 64, 512}) {
        Model model;
        const double target = 0.0162;  // c² / target² = 97.5 spp
        const PathTracerSearch search =
            find_path_tracer_spp([&](int spp) { return model(spp); }, target, start, 1024);
        ASSERT_TRUE(search.found) << "from " << start;
        EXPECT_EQ(search.above.spp, 64) << "from " << start;
        EXPECT_EQ(search.reached.spp, 128) << "from " << start;
        EXPECT_NEAR(search.spp, 0.16 * 0.16 / (target * target), 1e-9);
        EXPECT_NEAR(search.seconds, 0.5 * search.spp, 1e-9);
    }
}

TEST(PathTracerSearch, ReportsWhatItCouldNotReach) {
    Model model;
    const PathTracerSearch search = find_path_tracer_spp([&](int spp) { return model(spp); }, 0.001, 4, 64);
    EXPECT_FALSE(search.found);
    EXPECT_EQ(search.reached.spp, 64);
    EXPECT_EQ(model.measured, (std::vector<int>{4, 8, 16, 32, 64}));
}

TEST(PathTracerSearch, OneSampleReachingItNeedsNoInterpolation) {
    Model model;
    const PathTracerSearch search = find_path_tracer_spp([&](int spp) { return model(spp); }, 0.5, 16, 64);
    ASSERT_TRUE(search.found);
    EXPECT_EQ(search.above.spp, 0);
    EXPECT_EQ(search.reached.spp, 1);
    EXPECT_DOUBLE_EQ(search.spp, 1.0);
    EXPECT_EQ(model.measured, (std::vector<int>{16, 8, 4, 2, 1}));
}

}  // namespace
}  // namespace rad
