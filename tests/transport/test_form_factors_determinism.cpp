// The same seed gives the same matrix, bit for bit, whatever the number of threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {
namespace {

FormFactorMatrix with_threads(std::size_t threads, const PatchMesh& mesh, const FormFactorOptions& options) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return compute_form_factors(mesh, options);
}

void expect_identical(const FormFactorMatrix& a, const FormFactorMatrix& b) {
    EXPECT_EQ(a.row_begin, b.row_begin);
    EXPECT_EQ(a.column, b.column);
    EXPECT_EQ(a.value, b.value);  // float ==: bit for bit for finite values
}

class Determinism : public testing::TestWithParam<FormFactorMethod> {
  protected:
    const PatchMesh mesh_ = test::mesh(make_cornell_box(), 120.0);
    FormFactorOptions options() const {
        FormFactorOptions o;
        o.method = GetParam();
        o.rays = GetParam() == FormFactorMethod::hemisphere ? 1024 : 8;
        o.seed = 7;
        o.emitting_surfaces =
            emitting_surfaces(make_cornell_box());  // hemisphere: the light's columns analytic
        return o;
    }
};

TEST_P(Determinism, OneThreadAndTwoThreadsAgreeBitForBit) {
    const FormFactorMatrix one = with_threads(1, mesh_, options());
    const FormFactorMatrix two = with_threads(2, mesh_, options());
    ASSERT_GT(one.nonzeros(), 0u);
    expect_identical(one, two);
}

TEST_P(Determinism, TheSeedChangesTheEstimate) {
    FormFactorOptions other = options();
    other.seed = 8;
    EXPECT_NE(compute_form_factors(mesh_, options()).value, compute_form_factors(mesh_, other).value);
}

INSTANTIATE_TEST_SUITE_P(BothEstimators, Determinism,
                         testing::Values(FormFactorMethod::hemisphere, FormFactorMethod::analytic),
                         [](const auto& info) {
                             return info.param == FormFactorMethod::analytic ? "analytic" : "hemisphere";
                         });

}  // namespace
}  // namespace rad
