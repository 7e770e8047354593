#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"
#include "rad/util/progress.hpp"

namespace rad {

enum class FormFactorMethod { hemisphere, analytic };

// Rays per patch of the hemisphere estimator when FormFactorOptions::rays is 0. A patch's row is a Monte
// Carlo estimate of the light it gathers from other surfaces; the emitters' columns are computed
// analytically (form_factors_emitter_columns.hpp), so these rays carry only the indirect light, which is
// smooth and forgiving of noise (image error against rays: docs/measurements.md).
inline constexpr int kDefaultHemisphereRays = 2048;
// Shadow rays per pair of patches of the analytic estimator when FormFactorOptions::rays is 0: a 4 x 4
// stratified pairing.
inline constexpr int kDefaultAnalyticRays = 16;

struct FormFactorOptions {
    FormFactorMethod method = FormFactorMethod::hemisphere;
    // hemisphere: rays per patch (kDefaultHemisphereRays); analytic: shadow rays per pair of patches
    // (kDefaultAnalyticRays); 0 picks the method's default.
    int rays = 0;
    std::uint64_t seed = 1;
    std::size_t max_memory_bytes =
        0;  // budget for the pass; 0 means half the machine's (or container's) memory
    // Surfaces that emit (indices into the scene's surfaces; emitting_surfaces(scene) lists them). The
    // hemisphere estimator leaves their patches' columns to shadow rays aimed at them, drawn by power, which
    // is far less noisy for small bright sources (see form_factors_emitter_columns.hpp), unless they are
    // large; and each one's emitted luminance (the same order; empty: all alike), their weights.
    std::vector<std::uint32_t> emitting_surfaces;
    std::vector<double> emitted_luminance;
    bool enforce_reciprocity = false;  // replace A_i F_ij and A_j F_ji by their mean
    bool normalize_rows = false;       // scale rows to sum to exactly 1 (closed scenes only)
    // Only for finding a coarser patch size when the pass would not fit the memory budget: the size the
    // patches were made with (0: the longest patch edge stands in for it), and how many patches the scene
    // makes at a given size (count_patches bound to the scene). Without the count, the suggestion assumes
    // that patch counts scale as 1 / size², which edges shorter than a patch make optimistic.
    double patch_size = 0.0;
    std::function<std::size_t(double patch_size)> count_patches_at;
};

// How far a matrix is from what exact form factors satisfy. The reciprocity error of a pair is
// |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji) (1 when only one of the two is stored); the mean weighs
// each pair by the energy it exchanges, A_i F_ij + A_j F_ji.
struct FormFactorDiagnostics {
    double max_reciprocity_error = 0.0;
    double mean_reciprocity_error = 0.0;
    double min_row_sum = 0.0;
    double max_row_sum = 0.0;
    std::size_t rows_over_one = 0;  // rows that sum to more than 1 + kRowSumSlack
};

// A row of form factors sums to at most 1 (all of the patch's light goes somewhere); an estimate over it by
// more than this is reported (TransportReport::notes).
inline constexpr double kRowSumSlack = 0.01;

struct FormFactorReport {
    double seconds = 0.0;
    std::size_t memory_bytes = 0;  // the returned matrix
    std::size_t nonzeros = 0;
    std::uint64_t rays = 0;
    double escaped_ray_fraction = 0.0;  // hemisphere rays that left the scene
    // The share of the patches' area that other geometry covers (FormFactorMatrix::exposed).
    double covered_area_fraction = 0.0;
    // Of the returned matrix:
    double max_reciprocity_error = 0.0;  // max |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji)
    double mean_reciprocity_error = 0.0;
    double min_row_sum = 0.0;
    double max_row_sum = 0.0;
    std::size_t rows_over_one = 0;
    // Of the estimate before enforce_reciprocity and normalize_rows changed it (the same when neither is
    // set): the estimator's own accuracy.
    FormFactorDiagnostics estimate;
};

// F_ij with visibility, for every pair of patches, in rows sorted by column. Throws InputError for bad
// options and MemoryBudgetError when the estimated memory would exceed the budget (with a coarser patch
// size), and Cancelled when `progress` is cancelled. Results depend on the seed only, not on the number of
// threads.
FormFactorMatrix compute_form_factors(const PatchMesh& patches, const FormFactorOptions& options,
                                      FormFactorReport* report = nullptr, Progress* progress = nullptr);

}  // namespace rad
