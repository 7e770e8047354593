#pragma once

#include <cstddef>
#include <cstdint>

#include "rad/form_factor_matrix.hpp"
#include "rad/patches.hpp"
#include "rad/progress.hpp"

namespace rad {

enum class FormFactorMethod { hemisphere, analytic };

struct FormFactorOptions {
    FormFactorMethod method = FormFactorMethod::hemisphere;
    int rays = 0;  // hemisphere: rays per patch; analytic: shadow rays per pair; 0 picks the method's default
    std::uint64_t seed = 1;
    std::size_t max_memory_bytes = 0;  // budget for the matrix; 0 means half the machine's memory
    bool enforce_reciprocity = false;  // replace F_ij, F_ji by their area-weighted mean
    bool normalize_rows = false;       // scale rows to sum to exactly 1 (closed scenes only)
};

struct FormFactorReport {
    double seconds = 0.0;
    std::size_t memory_bytes = 0;
    std::uint64_t rays = 0;
    double escaped_ray_fraction = 0.0;   // rays that left the scene (hemisphere)
    double max_reciprocity_error = 0.0;  // max |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji)
    double min_row_sum = 0.0;
    double max_row_sum = 0.0;
};

// F_ij with visibility, for every pair of patches. Throws InputError (naming a coarser --patch-size) when
// the estimated matrix would exceed the memory budget, and Cancelled when `progress` is cancelled.
// Results depend on the seed only, not on the number of threads.
FormFactorMatrix compute_form_factors(const PatchMesh& patches, const FormFactorOptions& options,
                                      FormFactorReport* report = nullptr, Progress* progress = nullptr);

}  // namespace rad
