// Reciprocity A_i F_ij = A_j F_ji on the Cornell box, and the options that enforce it.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "transport/uniform/form_factors_diagnostics.hpp"

namespace rad {
namespace {

// 356 patches: the blocks, the light and every wall, small enough for a sanitizer build.
PatchMesh cornell_patches() {
    return test::mesh(make_cornell_box(), 100.0);
}

double find(const FormFactorMatrix& f, std::uint32_t i, std::uint32_t j) {
    const FormFactorRow row = f.row(i);
    for (std::size_t k = 0; k < row.size(); ++k)
        if (row.columns[k] == j) return row.values[k];
    return 0.0;
}

TEST(Reciprocity, AnalyticEstimatorOnTheCornellBoxWithinTwoPercent) {
    const PatchMesh mesh = cornell_patches();
    FormFactorOptions options;
    options.method = FormFactorMethod::analytic;
    FormFactorReport report;
    const FormFactorMatrix f = compute_form_factors(mesh, options, &report);
    EXPECT_LT(report.max_reciprocity_error, 0.02);
    EXPECT_GT(report.nonzeros, mesh.size() * 50);  // the check covered many pairs
    // The report's figure is right: recompute the error of every stored pair by brute force.
    double worst = 0.0;
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
        const FormFactorRow row = f.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            const std::uint32_t j = row.columns[k];
            // Exposed areas: the blocks cover parts of floor patches.
            const double forward = mesh.patches[i].area * f.exposed_fraction(i) * row.values[k];
            const double back = mesh.patches[j].area * f.exposed_fraction(j) * find(f, j, i);
            worst = std::max(worst, std::abs(forward - back) / std::max(forward, back));
        }
    }
    // The report diagnoses the rows before they became those of exposed parts: the same products A F, but the
    // stored exposed rows were divided and rounded to float again.
    EXPECT_NEAR(report.max_reciprocity_error, worst, 1e-4 * worst);
}

TEST(Reciprocity, RowsAreSortedAndHoldNoSelfFactor) {
    const PatchMesh mesh = cornell_patches();
    const FormFactorMatrix f = compute_form_factors(mesh, FormFactorOptions{});
    ASSERT_EQ(f.rows(), mesh.size());
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
        const FormFactorRow row = f.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            EXPECT_NE(row.columns[k], i);
            EXPECT_GT(row.values[k], 0.0f);
            if (k > 0) {
                EXPECT_LT(row.columns[k - 1], row.columns[k]);
            }
        }
    }
}

TEST(Reciprocity, EnforcingItMakesEveryPairReciprocal) {
    const PatchMesh mesh = cornell_patches();
    FormFactorOptions options;  // hemisphere: single rays make many pairs one-sided
    FormFactorReport raw;
    compute_form_factors(mesh, options, &raw);
    ASSERT_GT(raw.max_reciprocity_error, 0.5);

    options.enforce_reciprocity = true;
    FormFactorReport report;
    const FormFactorMatrix f = compute_form_factors(mesh, options, &report);
    EXPECT_LT(report.max_reciprocity_error, 1e-5);  // float rounding
    EXPECT_EQ(report.estimate.max_reciprocity_error, raw.max_reciprocity_error);
    // Energy is conserved: Σ A_i F_ij over the matrix does not change.
    double before = 0.0, after = 0.0;
    const FormFactorMatrix g = compute_form_factors(mesh, FormFactorOptions{});
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
        // Exposed areas: the blocks cover parts of floor patches.
        before += mesh.patches[i].area * g.exposed_fraction(i) * g.row(i).sum();
        after += mesh.patches[i].area * f.exposed_fraction(i) * f.row(i).sum();
    }
    EXPECT_NEAR(after / before, 1.0, 1e-6);
}

// Rows that sum over 1 (a sampled estimate's extra hits) are counted, and a normalized matrix has none.
TEST(RowSums, RowsOverOneAreCountedAndNormalizingRemovesThem) {
    const PatchMesh mesh = test::mesh(test::parallel_rectangles(1.0, 1.0, 1.0), 1.0);
    ASSERT_EQ(mesh.size(), 2u);
    FormFactorMatrix f;
    f.row_begin = {0, 1, 2};
    f.column = {1, 0};
    f.value = {1.05f, 0.5f};
    EXPECT_EQ(diagnose(f, mesh).rows_over_one, 1u);
    f.value[0] = 1.005f;  // within kRowSumSlack
    EXPECT_EQ(diagnose(f, mesh).rows_over_one, 0u);
    f.value[0] = 1.05f;
    normalize_rows(f);
    EXPECT_EQ(diagnose(f, mesh).rows_over_one, 0u);
}

}  // namespace
}  // namespace rad
