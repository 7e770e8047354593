#pragma once

// The first links of hierarchical radiosity, every ordered pair of base patches that may face each other:
// counted before any is made, their memory checked against the budget, and listed a block of receivers at a
// time so that the n² pairs never exist at once. Private to the library.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "rad/util/progress.hpp"
#include "transport/hierarchical/hierarchical_refine.hpp"

namespace rad {

// What the hierarchy holds per element: the element and its share of the tree's points and midpoints, its
// values (ρ, E, B, exposed and reaching shares, leaf scale), its leaf patch and the solves' vectors. The
// million-element run of docs/subdivision.md peaked at 1.98 GB, 1.30 GB of it links: 0.68 GB for 1.33
// million elements.
inline constexpr std::size_t kHierarchicalElementBytes = 512;
// Per first link: the link, in storage reserved for exactly the first links, and its place in the list of
// those refinement stopped at.
inline constexpr std::size_t kFirstLinkBytes = sizeof(HierarchicalLink) + sizeof(LinkCandidate);
// Per candidate of the block of first links being estimated: it and its estimate.
inline constexpr std::size_t kFirstLinkBlockBytes = sizeof(LinkCandidate) + sizeof(LinkEstimate);
// Per link refinement makes beyond them: the link three times over, as its vector grows by doubling and
// holds the old storage and the new at once, and its place in refinement's lists.
inline constexpr std::size_t kHierarchicalLinkBytes = 3 * sizeof(HierarchicalLink) + sizeof(LinkCandidate);

// The memory of the base patches and their first links, with the block being estimated: what must fit
// before anything is built.
std::size_t first_links_memory_estimate(std::size_t base_patches, std::uint64_t first_links);

// The memory of a hierarchy of `elements` elements and `links` links as refinement grows it: what
// refinement keeps within the budget.
std::size_t hierarchical_memory_estimate(std::size_t elements, std::uint64_t links);

// Could base patches a and b see each other at all: some corner of each strictly in front of the other's
// plane? Symmetric.
bool may_face(const PatchMesh& base, std::uint32_t a, std::uint32_t b);

// Per base patch as a receiver, the first links: how many other base patches it may face, and the lowest
// and highest of them (a receiver facing none has first > last), which bound the search when they are
// listed.
struct FirstLinks {
    std::vector<std::uint32_t> count, first, last;
    std::uint64_t total = 0;
};

// Counts the first links, checking their memory against `budget` (0: none) before building anything: the
// base patches alone, then (for large meshes) a sample of the pairs, then the exact count. Throws
// MemoryBudgetError with the figures (and a coarser patch size from options.patch_size and
// options.count_patches_at), and Cancelled when progress is cancelled.
FirstLinks count_first_links(const PatchMesh& base, const HierarchicalOptions& options, std::size_t budget,
                             Progress* progress);

// The first links received by base patches [begin, end), receiver by receiver, sources ascending, into
// `out`.
void list_first_links(const PatchMesh& base, const FirstLinks& first, std::uint32_t begin, std::uint32_t end,
                      std::vector<LinkCandidate>& out);

// "3 min", "2.5 h": a duration, for notes on long work.
std::string format_duration(double seconds);

}  // namespace rad
