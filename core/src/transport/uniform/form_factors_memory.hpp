#pragma once

#include <cstddef>
#include <string>

#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// An upper bound on the memory the form-factor pass needs for `patches` patches: the matrix (rows of at
// most min(rays, patches) entries for `hemisphere`, of at most `patches` for `analytic`, at 4 + 4 bytes per
// entry and 8 per row) plus the estimators' per-thread working memory.
std::size_t form_factor_memory_estimate(std::size_t patches, FormFactorMethod method, int rays);

// Throws MemoryBudgetError when the estimate exceeds the budget (options.max_memory_bytes, or half the
// usable memory when that is 0), with a patch size that would fit (see FormFactorOptions::count_patches_at).
void check_memory_budget(const PatchMesh& patches, const FormFactorOptions& options, int rays);

// "37.2 GB": bytes in powers of 1024, to three significant digits.
std::string format_bytes(double bytes);

}  // namespace rad
