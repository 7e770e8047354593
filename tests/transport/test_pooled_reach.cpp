// The ratio that corrects a pool of leaves' links to their measured reach (pooled_ratio): the priors
// min(cap, r · links) it gives add up to what the pool measured, also where some of them stop at their cap.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "transport/pooled_reach.hpp"

namespace rad {
namespace {

double priors(const std::vector<PoolLeaf>& pool, double ratio) {
    double sum = 0.0;
    for (const PoolLeaf& leaf : pool) sum += leaf.area * std::min(leaf.cap, ratio * leaf.links);
    return sum;
}

double measured(const std::vector<PoolLeaf>& pool) {
    double sum = 0.0;
    for (const PoolLeaf& leaf : pool) sum += leaf.area * leaf.measured;
    return sum;
}

TEST(PooledReach, WithNoPriorAtItsCapTheRatioIsThatOfTheSums) {
    const std::vector<PoolLeaf> pool = {{1.0, 0.5, 0.4}, {3.0, 0.7, 0.6}};
    EXPECT_NEAR(pooled_ratio(pool), (0.4 + 3.0 * 0.6) / (0.5 + 3.0 * 0.7), 1e-15);
}

TEST(PooledReach, ALeafAtItsCapLeavesTheRestOfTheMeasurementToTheOthers) {
    // Links 2 (a leaf in a corner, overestimated) and 0.5, measured 0.8 and 0.6: the ratio of the sums,
    // 1.4 / 2.5 = 0.56, gives priors 1 (capped) and 0.28, 1.28 in all, short of 1.4. With the first at its
    // cap the second must bring 0.4: r = 0.8.
    const std::vector<PoolLeaf> pool = {{1.0, 2.0, 0.8}, {1.0, 0.5, 0.6}};
    const double r = pooled_ratio(pool);
    EXPECT_NEAR(r, 0.8, 1e-12);
    EXPECT_NEAR(priors(pool, r), 1.4, 1e-12);
}

TEST(PooledReach, EveryPriorAtItsCapAndStillShortStopsThere) {
    // Caps of 0.5 (half of each leaf covered) against a measurement of 0.9 each: the priors cannot reach it.
    const std::vector<PoolLeaf> pool = {{1.0, 1.0, 0.9, 0.5}, {1.0, 0.8, 0.9, 0.5}};
    const double r = pooled_ratio(pool);
    EXPECT_NEAR(priors(pool, r), 1.0, 1e-12);
    EXPECT_NEAR(r, 0.5 / 0.8, 1e-12);  // the smallest ratio that puts both at their cap
}

TEST(PooledReach, LinksThatReachNothingLeaveTheRatioAtOne) {
    EXPECT_EQ(pooled_ratio(std::vector<PoolLeaf>{{1.0, 0.0, 0.5}}), 1.0);
    EXPECT_EQ(pooled_ratio(std::vector<PoolLeaf>{}), 1.0);
}

TEST(PooledReach, RandomPoolsAddUpToTheirMeasurement) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<PoolLeaf> pool(1 + trial % 50);
        for (PoolLeaf& leaf : pool) {
            leaf.area = 0.1 + unit(random);
            leaf.cap = 0.5 + 0.5 * unit(random);
            leaf.measured = leaf.cap * unit(random);
            leaf.links = 2.0 * unit(random);  // some well above what they measured
        }
        const double r = pooled_ratio(pool);
        ASSERT_GE(r, 0.0);
        // The measurement is within reach (every measured share is at most its cap), so it is met.
        EXPECT_NEAR(priors(pool, r), measured(pool), 1e-9 * measured(pool)) << "trial " << trial;
    }
}

}  // namespace
}  // namespace rad
