// An opaque square between two parallel unit squares takes from F exactly what its shadow covers.
//
// The unit squares face each other at distance 1 (F = 0.199825 unoccluded). A 0.4 x 0.4 square at height
// 0.75 faces the lower one; its shadow on the upper square, seen from any point of the lower one, lies
// wholly inside the upper square, so the lower square loses to the occluder exactly the F it gives it:
// F(lower -> upper) = 0.199825 - F(lower -> occluder). The occluder's back blocks the upper square's rays.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/geometry/point_polygon_factor.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {
namespace {

constexpr std::uint32_t kLower = 0, kUpper = 1, kOccluder = 2;

Scene occluded_squares() {
    return test::TestSceneBuilder()
        .add("lower", {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}})
        .add("upper", {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}})
        .add("occluder", {{0.3, 0.75, 0.3}, {0.7, 0.75, 0.3}, {0.7, 0.75, 0.7}, {0.3, 0.75, 0.7}})
        .build();
}

// F(lower -> occluder) by the midpoint rule on a 400 x 400 grid of Lambert's point factor: independent of
// both estimators, accurate to about 1e-6.
double lower_to_occluder_reference() {
    const std::vector<glm::dvec3> occluder = {
        {0.3, 0.75, 0.3}, {0.7, 0.75, 0.3}, {0.7, 0.75, 0.7}, {0.3, 0.75, 0.7}};
    constexpr int kSteps = 400;
    double sum = 0.0;
    for (int u = 0; u < kSteps; ++u) {
        for (int v = 0; v < kSteps; ++v) {
            const glm::dvec3 x((u + 0.5) / kSteps, 0.0, (v + 0.5) / kSteps);
            sum += point_polygon_factor(x, {0, 1, 0}, occluder);
        }
    }
    return sum / (kSteps * kSteps);
}

class Occluder : public testing::TestWithParam<FormFactorMethod> {};

TEST_P(Occluder, TakesWhatItsShadowCovers) {
    const PatchMesh mesh = test::mesh(occluded_squares(), 0.125);
    FormFactorOptions options;
    options.method = GetParam();
    const FormFactorMatrix f = compute_form_factors(mesh, options);

    const double to_occluder = test::surface_factor(f, mesh, kLower, kOccluder);
    const double reference = lower_to_occluder_reference();
    ASSERT_GT(reference, 0.05);  // the occluder hides over a quarter of what the lower square sees
    // Absolute tolerances: 2 % and 0.5 % of the unoccluded 0.199825, as for the unoccluded pair.
    const double tolerance = GetParam() == FormFactorMethod::analytic ? 0.001 : 0.004;
    EXPECT_NEAR(to_occluder, reference, tolerance);
    EXPECT_NEAR(test::surface_factor(f, mesh, kLower, kUpper), 0.199825 - reference, tolerance);
    // From above, the occluder shows its back: it blocks but receives nothing, and takes the same share.
    EXPECT_EQ(test::surface_factor(f, mesh, kUpper, kOccluder), 0.0);
    EXPECT_NEAR(test::surface_factor(f, mesh, kUpper, kLower), 0.199825 - reference, tolerance);
}

INSTANTIATE_TEST_SUITE_P(BothEstimators, Occluder,
                         testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) {
                             return info.param == FormFactorMethod::analytic ? "analytic" : "hemisphere";
                         });

}  // namespace
}  // namespace rad
