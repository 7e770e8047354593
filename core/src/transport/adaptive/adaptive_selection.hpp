#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/element_tree.hpp"

namespace rad {

// What the criteria asked for, per leaf: ≥ 1 asks to split, larger asks harder.
struct SplitRequests {
    std::span<const double> gradient;
    std::span<const double> shadow;
};

struct SplitChoice {
    std::vector<std::uint32_t> leaves;  // indices into the pass's leaves, ascending
    std::size_t gradient = 0;           // leaves each criterion asked to split
    std::size_t shadow = 0;
    std::size_t too_small = 0;  // asked, but at the minimum size
    bool over_budget = false;   // asked and large enough, but not all fit under max_leaves
};

// The leaves to split: those asked by either criterion whose longest edge is at least twice the minimum size
// (min_patch_size, or when it is 0 the base patch's longest edge / 8), at most as many as keep the leaves
// within max_leaves (each split adds three). When not all fit, the largest area × request go first.
SplitChoice choose_splits(const ElementTree& tree, std::span<const std::uint32_t> elements,
                          const SplitRequests& requests, double min_patch_size, std::size_t max_leaves);

}  // namespace rad
