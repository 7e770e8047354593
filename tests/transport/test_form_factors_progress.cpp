// The pass reports its progress, tells what it will do and cost in a note, and stops when cancelled.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "transport/uniform/form_factors_memory.hpp"

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

TEST(FormFactorProgress, NotesPatchesRaysAndMemoryOnceAtTheStart) {
    const PatchMesh mesh = test::mesh(make_cornell_box(), 150.0);
    const std::string patches = std::to_string(mesh.size()) + " patches";
    Progress progress;
    compute_form_factors(mesh, FormFactorOptions{}, nullptr, &progress);
    std::vector<ProgressNote> notes = progress.notes();
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0].stage, "form factors");
    const std::size_t hemisphere =
        form_factor_memory_estimate(mesh.size(), FormFactorMethod::hemisphere, 2048);
    EXPECT_EQ(notes[0].text,
              patches + " × 2048 rays, about " + format_bytes(static_cast<double>(hemisphere)));

    FormFactorOptions analytic;
    analytic.method = FormFactorMethod::analytic;
    analytic.rays = 4;
    compute_form_factors(mesh, analytic, nullptr, &progress);
    notes = progress.notes(1);
    ASSERT_EQ(notes.size(), 1u);
    const std::size_t pairs = form_factor_memory_estimate(mesh.size(), FormFactorMethod::analytic, 4);
    EXPECT_EQ(notes[0].text,
              patches + ", 4 shadow rays per pair, about " + format_bytes(static_cast<double>(pairs)));
}

TEST(FormFactorProgress, EmptyMeshSetsNoNote) {
    Progress progress;
    compute_form_factors(PatchMesh{}, FormFactorOptions{}, nullptr, &progress);
    EXPECT_EQ(progress.stage(), "form factors");
    EXPECT_TRUE(progress.notes().empty());
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
