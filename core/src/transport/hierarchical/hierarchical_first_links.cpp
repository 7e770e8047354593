#include "transport/hierarchical/hierarchical_first_links.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <utility>

#include "rad/util/error.hpp"
#include "transport/uniform/form_factors_memory.hpp"

namespace rad {

namespace {

// Up to this many pair tests (well under a second) the first links are simply counted. Above, a sample of
// the pairs tells first whether they could fit at all, so that a mesh far over the budget is refused at once
// rather than after minutes of counting.
constexpr double kCountedPairs = 5e7;
constexpr std::uint64_t kSampledPairs = std::uint64_t{1} << 20;
// The sample refuses only when even this many standard errors fewer facing pairs would not fit.
constexpr double kSampleSigmas = 4.0;
constexpr std::uint32_t kNone = 0xffffffffu;  // FirstLinks::first of a receiver facing nothing

// Σ count × bytes, or the largest size_t when that overflows.
std::size_t sum_of_products(std::initializer_list<std::pair<std::uint64_t, std::size_t>> terms) {
    constexpr std::size_t kMost = std::numeric_limits<std::size_t>::max();
    std::size_t sum = 0;
    for (const auto& [count, bytes] : terms) {
        if (count > (kMost - sum) / bytes) return kMost;
        sum += static_cast<std::size_t>(count) * bytes;
    }
    return sum;
}

std::uint64_t next_random(std::uint64_t& state) {  // splitmix64
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double ordered_pairs(std::size_t n) {
    return n < 2 ? 0.0 : static_cast<double>(n) * static_cast<double>(n - 1);
}

// The share of ordered pairs that may face each other, from kSampledPairs pairs drawn at random (seeded,
// so the same mesh always gives the same share).
double sampled_share(const PatchMesh& base) {
    const std::uint64_t n = base.size();
    std::uint64_t state = 0x6669727374ull, facing = 0;
    for (std::uint64_t k = 0; k < kSampledPairs; ++k) {
        const auto r = static_cast<std::uint32_t>(next_random(state) % n);
        auto s = static_cast<std::uint32_t>(next_random(state) % (n - 1));
        if (s >= r) ++s;
        facing += may_face(base, std::min(r, s), std::max(r, s)) ? 1 : 0;
    }
    return static_cast<double>(facing) / static_cast<double>(kSampledPairs);
}

// Per base patch, the others it may face: each unordered pair tested once, on all threads.
FirstLinks exact_counts(const PatchMesh& base, Progress* progress) {
    const auto n = static_cast<std::uint32_t>(base.size());
    const auto fresh = [n] {
        FirstLinks f;
        f.count.assign(n, 0);
        f.first.assign(n, kNone);
        f.last.assign(n, 0);
        return f;
    };
    tbb::enumerable_thread_specific<FirstLinks> local(fresh);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, n),
                      [&](const tbb::blocked_range<std::uint32_t>& rows) {
                          FirstLinks& f = local.local();
                          for (std::uint32_t a = rows.begin(); a < rows.end(); ++a) {
                              if (progress && progress->cancelled()) return;
                              for (std::uint32_t b = a + 1; b < n; ++b) {
                                  if (!may_face(base, a, b)) continue;
                                  ++f.count[a];
                                  ++f.count[b];
                                  f.first[a] = std::min(f.first[a], b);
                                  f.last[a] = b;
                                  f.first[b] = std::min(f.first[b], a);
                                  f.last[b] = std::max(f.last[b], a);
                              }
                              if (progress) progress->advance(n - a - 1);
                          }
                      });
    if (progress && progress->cancelled()) throw Cancelled{};
    FirstLinks all = fresh();
    for (const FirstLinks& f : local) {
        for (std::uint32_t k = 0; k < n; ++k) {
            all.count[k] += f.count[k];
            all.first[k] = std::min(all.first[k], f.first[k]);
            all.last[k] = std::max(all.last[k], f.last[k]);
        }
    }
    for (std::uint32_t c : all.count) all.total += c;
    return all;
}

double longest_edge(const PatchMesh& base) {
    double longest = 0.0;
    for (std::size_t i = 0; i < base.size(); ++i) {
        const int n = base.corner_count(i);
        for (int k = 0; k < n; ++k)
            longest = std::max(longest, glm::length(base.points[base.corners[i][k]] -
                                                    base.points[base.corners[i][(k + 1) % n]]));
    }
    return longest;
}

// A base patch size whose first links would fit, rounded up to three digits; 0 if none is found. The share
// of pairs that face each other is taken to stay as it is, and base patch counts to scale about as
// 1 / size², which gives the first guess; with the scene's own count, the guess grows until it really fits.
double coarser_base_size(const PatchMesh& base, const HierarchicalOptions& options, std::size_t budget,
                         double share) {
    const auto fits = [&](std::size_t m) {
        return first_links_memory_estimate(m, static_cast<std::uint64_t>(ordered_pairs(m) * share)) <= budget;
    };
    std::size_t lo = 0, hi = base.size();
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo + 1) / 2;
        if (fits(mid)) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    const double size = options.patch_size > 0.0 ? options.patch_size : longest_edge(base);
    if (lo == 0 || !(size > 0.0)) return 0.0;
    // The margin covers the rounding of edges into whole patches.
    double guess = size * std::sqrt(static_cast<double>(base.size()) / static_cast<double>(lo)) * 1.05;
    if (!options.count_patches_at) return round_up_3_digits(guess);
    constexpr int kAttempts = 200;
    for (int attempt = 0; attempt < kAttempts; ++attempt, guess *= 1.05) {
        const double rounded = round_up_3_digits(guess);
        if (fits(options.count_patches_at(rounded))) return rounded;
    }
    return 0.0;
}

[[noreturn]] void refuse(const PatchMesh& base, const HierarchicalOptions& options, std::size_t budget,
                         double first_links, bool sampled) {
    const std::size_t n = base.size();
    const std::size_t need = first_links_memory_estimate(n, static_cast<std::uint64_t>(first_links));
    std::ostringstream msg;
    msg << "hierarchical radiosity needs about " << format_bytes(static_cast<double>(need))
        << " for the first links of " << n << " base patches (" << (sampled ? "about " : "")
        << static_cast<std::uint64_t>(first_links) << " pairs that may face each other"
        << (sampled ? ", from a sample" : "") << "), over the budget of "
        << format_bytes(static_cast<double>(budget));
    const double share = first_links / std::max(1.0, ordered_pairs(n));
    throw MemoryBudgetError(msg.str(), need, budget, n, coarser_base_size(base, options, budget, share));
}

}  // namespace

std::size_t first_links_memory_estimate(std::size_t base_patches, std::uint64_t first_links) {
    const std::uint64_t block = std::min<std::uint64_t>(first_links, kFirstLinkBlock);
    return sum_of_products({{base_patches, kHierarchicalElementBytes},
                            {first_links, kFirstLinkBytes},
                            {block, kFirstLinkBlockBytes}});
}

std::size_t hierarchical_memory_estimate(std::size_t elements, std::uint64_t links) {
    return sum_of_products({{elements, kHierarchicalElementBytes}, {links, kHierarchicalLinkBytes}});
}

bool may_face(const PatchMesh& base, std::uint32_t a, std::uint32_t b) {
    auto in_front = [&](std::uint32_t of, std::uint32_t seen) {
        const Patch& p = base.patches[of];
        const double tiny = 1e-9 * std::sqrt(p.area);
        for (int k = 0; k < base.corner_count(seen); ++k)
            if (glm::dot(p.normal, base.points[base.corners[seen][k]] - p.centroid) > tiny) return true;
        return false;
    };
    return in_front(a, b) && in_front(b, a);
}

FirstLinks count_first_links(const PatchMesh& base, const HierarchicalOptions& options, std::size_t budget,
                             Progress* progress) {
    const std::size_t n = base.size();
    const double pairs = ordered_pairs(n);
    if (budget > 0 && pairs / 2.0 > kCountedPairs) {
        const double share = sampled_share(base);
        const double error = std::sqrt(share * (1.0 - share) / static_cast<double>(kSampledPairs));
        const double fewest = std::max(0.0, share - kSampleSigmas * error) * pairs;
        if (first_links_memory_estimate(n, static_cast<std::uint64_t>(fewest)) > budget)
            refuse(base, options, budget, share * pairs, true);
    }
    if (progress) progress->begin("counting the first links", static_cast<std::uint64_t>(pairs / 2.0));
    FirstLinks first = exact_counts(base, progress);
    if (budget > 0 && first_links_memory_estimate(n, first.total) > budget)
        refuse(base, options, budget, static_cast<double>(first.total), false);
    return first;
}

void list_first_links(const PatchMesh& base, const FirstLinks& first, std::uint32_t begin, std::uint32_t end,
                      std::vector<LinkCandidate>& out) {
    std::vector<std::size_t> offset(end - begin + 1, 0);
    for (std::uint32_t r = begin; r < end; ++r) offset[r - begin + 1] = offset[r - begin] + first.count[r];
    out.resize(offset.back());
    tbb::parallel_for(begin, end, [&](std::uint32_t r) {
        std::size_t k = offset[r - begin];
        // The same test, on the same pair in the same order, as the count, so the offsets hold; only
        // between the receiver's first and last source.
        for (std::uint32_t s = first.first[r]; first.count[r] > 0 && s <= first.last[r]; ++s)
            if (s != r && may_face(base, std::min(r, s), std::max(r, s))) out[k++] = {r, s};
    });
}

std::string format_duration(double seconds) {
    char text[32];
    if (seconds < 90.0) {
        std::snprintf(text, sizeof text, "%.0f s", seconds);
    } else if (seconds < 90.0 * 60.0) {
        std::snprintf(text, sizeof text, "%.0f min", seconds / 60.0);
    } else if (seconds < 48.0 * 3600.0) {
        std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
    } else {
        std::snprintf(text, sizeof text, "%.0f days", seconds / 86400.0);
    }
    return text;
}

}  // namespace rad
