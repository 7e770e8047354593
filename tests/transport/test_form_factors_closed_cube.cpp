// A closed cube seen from inside: every row sums to 1, and face to face F(opposite) + 4 F(adjacent) = 1.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {
namespace {

constexpr double kRowSumTolerance = 0.01;  // the target

class ClosedCube : public testing::TestWithParam<FormFactorMethod> {
  protected:
    // builtin:cube in 4 x 4 patches per face; surfaces: top, bottom, left, right, back, front.
    const PatchMesh mesh_ = test::mesh(make_cube(), 0.25);

    FormFactorMatrix compute(FormFactorReport& report) const {
        FormFactorOptions options;
        options.method = GetParam();
        return compute_form_factors(mesh_, options, &report);
    }
};

TEST_P(ClosedCube, RowsSumToOne) {
    FormFactorReport report;
    compute(report);
    EXPECT_NEAR(report.min_row_sum, 1.0, kRowSumTolerance);
    EXPECT_NEAR(report.max_row_sum, 1.0, kRowSumTolerance);
    EXPECT_EQ(report.escaped_ray_fraction, 0.0);
}

TEST_P(ClosedCube, FaceToFaceFactorsMatchTheClosedForms) {
    FormFactorReport report;
    const FormFactorMatrix f = compute(report);
    const double tolerance = GetParam() == FormFactorMethod::analytic ? 0.005 : 0.02;
    EXPECT_NEAR(test::surface_factor(f, mesh_, 0, 1) / 0.199825, 1.0, tolerance);  // top to bottom
    for (std::uint32_t side = 2; side < 6; ++side) {
        EXPECT_NEAR(test::surface_factor(f, mesh_, 0, side) / 0.200044, 1.0, tolerance) << "side " << side;
    }
    EXPECT_EQ(test::surface_factor(f, mesh_, 0, 0), 0.0);  // a flat face cannot see itself
}

TEST_P(ClosedCube, NormalizedRowsSumToExactlyOne) {
    FormFactorOptions options;
    options.method = GetParam();
    options.normalize_rows = true;
    FormFactorReport report;
    compute_form_factors(mesh_, options, &report);
    EXPECT_NEAR(report.min_row_sum, 1.0, 1e-6);
    EXPECT_NEAR(report.max_row_sum, 1.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(BothEstimators, ClosedCube,
                         testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) {
                             return info.param == FormFactorMethod::analytic ? "analytic" : "hemisphere";
                         });

}  // namespace
}  // namespace rad
