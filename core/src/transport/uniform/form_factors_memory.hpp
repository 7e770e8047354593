#pragma once

#include <cstddef>
#include <string>

#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// An upper bound on the memory the form-factor pass needs for `patches` patches: the matrix (rows of at
// most min(rays, patches) entries for `hemisphere`, of at most `patches` for `analytic`, at 4 + 4 bytes per
// entry and 8 per row) plus the estimators' per-thread working memory.
std::size_t form_factor_memory_estimate(std::size_t patches, FormFactorMethod method, int rays);

// The budget a setting of `max_memory_bytes` gives: itself, or half the usable memory when it is 0; 0 when
// the machine would not say (no budget).
std::size_t memory_budget_bytes(std::size_t max_memory_bytes);

// The most patches, up to `at_most`, whose estimate fits `budget` (0 when not even one does).
std::size_t form_factor_patches_that_fit(std::size_t budget, FormFactorMethod method, int rays,
                                         std::size_t at_most);

// Throws MemoryBudgetError when the estimate exceeds the budget (memory_budget_bytes of
// options.max_memory_bytes), with a patch size that would fit (see FormFactorOptions::count_patches_at).
void check_memory_budget(const PatchMesh& patches, const FormFactorOptions& options, int rays);

// A patch size rounded up to three significant digits, so that "or larger" stays true.
double round_up_3_digits(double size);

// "37.2 GB": bytes in powers of 1024, to three significant digits.
std::string format_bytes(double bytes);

}  // namespace rad
