// The pass reports its progress and stops when cancelled.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {
namespace {

TEST(FormFactorProgress, ReachesTheEndOfItsStage) {
    const PatchMesh mesh = test::mesh(make_cornell_box(), 150.0);
    Progress progress;
    FormFactorReport report;
    compute_form_factors(mesh, FormFactorOptions{}, &report, &progress);
    EXPECT_EQ(progress.stage(), "form factors");
    EXPECT_DOUBLE_EQ(progress.fraction(), 1.0);
    EXPECT_GT(report.seconds, 0.0);
    EXPECT_GT(report.memory_bytes, 0u);
}

TEST(FormFactorProgress, CancelledBeforeItStartsThrowsCancelled) {
    const PatchMesh mesh = test::mesh(make_cornell_box(), 150.0);
    Progress progress;
    progress.cancel();
    EXPECT_THROW(compute_form_factors(mesh, FormFactorOptions{}, nullptr, &progress), Cancelled);
    EXPECT_LT(progress.fraction(), 1.0);
}

TEST(FormFactorProgress, EmptyMeshGivesAnEmptyMatrix) {
    const PatchMesh empty;
    FormFactorReport report;
    const FormFactorMatrix f = compute_form_factors(empty, FormFactorOptions{}, &report);
    EXPECT_EQ(f.rows(), 0u);
    EXPECT_EQ(f.nonzeros(), 0u);
}

}  // namespace
}  // namespace rad
