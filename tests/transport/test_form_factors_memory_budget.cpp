// The memory estimate stops a pass that would not fit, naming a --patch-size that does.
#include <gtest/gtest.h>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/util/error.hpp"
#include "transport/uniform/form_factors_memory.hpp"

namespace rad {
namespace {

TEST(MemoryEstimate, BoundsWhatThePassAllocates) {
    const PatchMesh mesh = test::mesh(make_cornell_box(), 100.0);
    for (FormFactorMethod method : {FormFactorMethod::hemisphere, FormFactorMethod::analytic}) {
        FormFactorOptions options;
        options.method = method;
        options.rays = 64;
        const FormFactorMatrix f = compute_form_factors(mesh, options);
        EXPECT_LE(f.memory_bytes(), form_factor_memory_estimate(mesh.size(), method, 64));
    }
    // n patches, at most min(rays, n) entries per row of 8 bytes, 8 bytes per row pointer, plus working
    // memory.
    EXPECT_GE(form_factor_memory_estimate(1000, FormFactorMethod::analytic, 16), 1000u * 1000u * 8u + 8008u);
    EXPECT_GE(form_factor_memory_estimate(1000, FormFactorMethod::hemisphere, 100),
              1000u * 100u * 8u + 8008u);
    EXPECT_LT(form_factor_memory_estimate(1000, FormFactorMethod::hemisphere, 100), 1000u * 1000u * 8u);
}

TEST(MemoryBudget, OverBudgetNamesACoarserPatchSizeThatFits) {
    const Scene cornell = make_cornell_box();
    const double patch_size = 50.0;
    const PatchMesh mesh = test::mesh(cornell, patch_size);
    FormFactorOptions options;
    options.method = FormFactorMethod::analytic;
    options.patch_size = patch_size;
    options.count_patches_at = [&cornell](double size) { return count_patches(cornell, size); };
    options.max_memory_bytes = form_factor_memory_estimate(mesh.size() / 4, options.method, 16);
    try {
        compute_form_factors(mesh, options);
        FAIL() << "no error for a budget of a sixteenth of the matrix";
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.patches, mesh.size());
        EXPECT_GT(e.needed_bytes, e.budget_bytes);
        EXPECT_EQ(e.setting(), "max_memory");
        const std::string message = e.what();
        EXPECT_NE(message.find("form factors need about"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(mesh.size()) + " patches"), std::string::npos) << message;
        const double suggested = e.coarser_patch_size;
        EXPECT_GT(suggested, patch_size);
        // The suggestion must really fit, and not be needlessly coarse.
        const PatchMesh coarser = test::mesh(cornell, suggested);
        EXPECT_LE(form_factor_memory_estimate(coarser.size(), options.method, 16), options.max_memory_bytes);
        EXPECT_GT(coarser.size(), mesh.size() / 8);
    }
}

// Without the scene's patch count the suggestion scales the longest patch edge by sqrt(patch ratio).
TEST(MemoryBudget, WithoutTheSceneTheSuggestionScalesTheLongestEdge) {
    const PatchMesh mesh = test::mesh(test::parallel_rectangles(1, 1, 1), 0.125);  // 2 x 64 patches
    FormFactorOptions options;
    options.method = FormFactorMethod::analytic;
    options.max_memory_bytes = form_factor_memory_estimate(32, options.method, 16);
    try {
        compute_form_factors(mesh, options);
        FAIL();
    } catch (const MemoryBudgetError& e) {
        // 128 patches to 32: twice the edge, with a 5 % margin.
        EXPECT_DOUBLE_EQ(e.coarser_patch_size, 0.263) << e.what();
    }
}

TEST(MemoryBudget, ABudgetTooSmallForOnePatchAsksForMore) {
    const PatchMesh mesh = test::mesh(test::parallel_rectangles(1, 1, 1), 1.0);
    FormFactorOptions options;
    options.max_memory_bytes = 10;
    try {
        compute_form_factors(mesh, options);
        FAIL();
    } catch (const MemoryBudgetError& e) {
        EXPECT_EQ(e.coarser_patch_size, 0.0);
        EXPECT_GT(e.needed_bytes, e.budget_bytes);
    }
}

TEST(Options, NegativeRaysAreAnInputError) {
    const PatchMesh mesh = test::mesh(test::parallel_rectangles(1, 1, 1), 1.0);
    FormFactorOptions options;
    options.rays = -1;
    try {
        compute_form_factors(mesh, options);
        FAIL();
    } catch (const SettingError& e) {
        EXPECT_EQ(e.setting(), "rays");
        EXPECT_EQ(std::string(e.what()).find("rays: "), 0u) << e.what();
    }
}

}  // namespace
}  // namespace rad
