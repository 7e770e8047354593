#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "rad/form_factor_matrix.hpp"
#include "rad/patches.hpp"
#include "rad/progress.hpp"

namespace rad {

enum class FormFactorMethod { hemisphere, analytic };

struct FormFactorOptions {
    FormFactorMethod method = FormFactorMethod::hemisphere;
    // hemisphere: rays per patch (default 4096); analytic: shadow rays per pair of patches (default 16);
    // 0 picks the method's default.
    int rays = 0;
    std::uint64_t seed = 1;
    std::size_t max_memory_bytes =
        0;  // budget for the pass; 0 means half the machine's (or container's) memory
    bool enforce_reciprocity = false;  // replace A_i F_ij and A_j F_ji by their mean
    bool normalize_rows = false;       // scale rows to sum to exactly 1 (closed scenes only)
    // Only for naming a coarser --patch-size when the pass would not fit the memory budget: the size the
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
};

struct FormFactorReport {
    double seconds = 0.0;
    std::size_t memory_bytes = 0;  // the returned matrix
    std::size_t nonzeros = 0;
    std::uint64_t rays = 0;
    double escaped_ray_fraction = 0.0;  // rays that left the scene (hemisphere)
    // The share of the patches' area that other geometry covers (FormFactorMatrix::exposed).
    double covered_area_fraction = 0.0;
    // Of the returned matrix:
    double max_reciprocity_error = 0.0;  // max |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji)
    double mean_reciprocity_error = 0.0;
    double min_row_sum = 0.0;
    double max_row_sum = 0.0;
    // Of the estimate before enforce_reciprocity and normalize_rows changed it (the same when neither is
    // set): the estimator's own accuracy.
    FormFactorDiagnostics estimate;
};

// F_ij with visibility, for every pair of patches, in rows sorted by column. Throws InputError for bad
// options and when the estimated memory would exceed the budget (naming a coarser --patch-size), and
// Cancelled when `progress` is cancelled. Results depend on the seed only, not on the number of threads.
FormFactorMatrix compute_form_factors(const PatchMesh& patches, const FormFactorOptions& options,
                                      FormFactorReport* report = nullptr, Progress* progress = nullptr);

}  // namespace rad
