// The analytic estimator against the closed forms of docs/analytic.md: within 0.5 %.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {
namespace {

using test::Configuration;

constexpr double kTolerance = 0.005;  // relative, the target for `analytic`

class AnalyticEstimator : public testing::TestWithParam<Configuration> {
  protected:
    static double surface_factor(const Configuration& c, double patch_size) {
        const PatchMesh mesh = test::mesh(c.scene(), patch_size);
        FormFactorOptions options;
        options.method = FormFactorMethod::analytic;
        return test::surface_factor(compute_form_factors(mesh, options), mesh, 0, 1);
    }
};

TEST_P(AnalyticEstimator, ClosedFormMatchesTheTable) {
    EXPECT_NEAR(GetParam().closed_form(), GetParam().table_value, 1e-6);
}

// One patch per rectangle: the adaptive quadrature alone must reach the target, shared edge included.
TEST_P(AnalyticEstimator, OnePatchPerRectangle) {
    const Configuration& c = GetParam();
    const double f = surface_factor(c, c.longest_side());
    EXPECT_NEAR(f / c.table_value, 1.0, kTolerance) << "F = " << f;
}

// A 4 x 4 mesh: the patches along a shared edge touch, where the kernel is singular.
TEST_P(AnalyticEstimator, MeshedRectangles) {
    const Configuration& c = GetParam();
    const double f = surface_factor(c, c.longest_side() / 4);
    EXPECT_NEAR(f / c.table_value, 1.0, kTolerance) << "F = " << f;
}

INSTANTIATE_TEST_SUITE_P(AnalyticMd, AnalyticEstimator, testing::ValuesIn(test::configurations()),
                         test::configuration_name);

}  // namespace
}  // namespace rad
