#include "transport/uniform/form_factors_memory.hpp"

#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <sstream>

#include "rad/util/error.hpp"
#include "util/system_memory.hpp"

namespace rad {

namespace {

constexpr double kBytesPerEntry = sizeof(std::uint32_t) + sizeof(float);
constexpr double kBytesPerRow = sizeof(std::uint64_t);

double longest_patch_edge(const PatchMesh& patches) {
    double longest = 0.0;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const glm::uvec4& c = patches.corners[i];
        const int n = patches.corner_count(i);
        for (int k = 0; k < n; ++k) {
            longest = std::max(longest, glm::length(patches.points[c[k]] - patches.points[c[(k + 1) % n]]));
        }
    }
    return longest;
}

// A patch size whose pass fits the budget, rounded up to three digits; 0 if none is found. Patch counts
// scale about as 1 / size², which gives the first guess; with the scene's own count, the guess grows until
// the count really fits.
double coarser_patch_size(const FormFactorOptions& options, int rays, std::size_t budget, double size,
                          std::size_t patches, std::size_t fit) {
    // The margin covers the rounding of edges into whole patches.
    double guess = size * std::sqrt(static_cast<double>(patches) / static_cast<double>(fit)) * 1.05;
    if (!options.count_patches_at) return round_up_3_digits(guess);
    constexpr int kAttempts = 200;
    for (int attempt = 0; attempt < kAttempts; ++attempt, guess *= 1.05) {
        const double rounded = round_up_3_digits(guess);
        if (form_factor_memory_estimate(options.count_patches_at(rounded), options.method, rays) <= budget) {
            return rounded;
        }
    }
    return 0.0;
}

}  // namespace

double round_up_3_digits(double size) {
    const double scale = std::pow(10.0, std::floor(std::log10(size)) - 2.0);
    return std::ceil(size / scale) * scale;
}

std::string format_bytes(double bytes) {
    const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB"};
    int u = 0;
    while (bytes >= 1024.0 && u < 5) {
        bytes /= 1024.0;
        ++u;
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %s", bytes, units[u]);
    return text;
}

std::size_t memory_budget_bytes(std::size_t max_memory_bytes) {
    return max_memory_bytes > 0 ? max_memory_bytes : usable_memory_bytes() / 2;
}

std::size_t form_factor_patches_that_fit(std::size_t budget, FormFactorMethod method, int rays,
                                         std::size_t at_most) {
    std::size_t lo = 0, hi = at_most;
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo + 1) / 2;
        if (form_factor_memory_estimate(mid, method, rays) <= budget) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    return lo;
}

std::size_t form_factor_memory_estimate(std::size_t patches, FormFactorMethod method, int rays) {
    const auto n = static_cast<double>(patches);
    const auto threads = static_cast<double>(tbb::this_task_arena::max_concurrency());
    double row_bound = n;
    double per_thread = 0.0;
    if (method == FormFactorMethod::hemisphere) {
        row_bound = std::min(n, static_cast<double>(rays));
        // The dense accumulator and the rays of one patch.
        per_thread = n * sizeof(double) + static_cast<double>(rays) * (32.0 + 8.0 + 2.0 * 16.0);
    } else {
        // The candidate list and the shadow rays of one row.
        per_thread = n * (16.0 + static_cast<double>(rays) * (32.0 + 1.0));
    }
    const double bytes = n * row_bound * kBytesPerEntry + (n + 1.0) * kBytesPerRow + threads * per_thread;
    return bytes >= 1e19 ? std::numeric_limits<std::size_t>::max() : static_cast<std::size_t>(bytes);
}

void check_memory_budget(const PatchMesh& patches, const FormFactorOptions& options, int rays) {
    const std::size_t budget = memory_budget_bytes(options.max_memory_bytes);
    if (budget == 0) return;  // the machine would not say; let the allocator decide
    const std::size_t n = patches.size();
    const std::size_t need = form_factor_memory_estimate(n, options.method, rays);
    if (need <= budget) return;

    std::ostringstream msg;
    msg << "form factors need about " << format_bytes(static_cast<double>(need)) << " for " << n
        << " patches, over the budget of " << format_bytes(static_cast<double>(budget));
    const std::size_t fit = form_factor_patches_that_fit(budget, options.method, rays, n);
    const double size = options.patch_size > 0.0 ? options.patch_size : longest_patch_edge(patches);
    const double coarser =
        fit == 0 || !(size > 0.0) ? 0.0 : coarser_patch_size(options, rays, budget, size, n, fit);
    throw MemoryBudgetError(msg.str(), need, budget, n, coarser);
}

}  // namespace rad
