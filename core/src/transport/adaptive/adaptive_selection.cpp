#include "transport/adaptive/adaptive_selection.hpp"

#include <algorithm>

namespace rad {

namespace {

// Elements exactly at the limit still split: their quarters come out at the minimum size, not below it.
constexpr double kSizeSlack = 1e-9;
constexpr double kDefaultLevels = 8.0;  // the default minimum is a base patch's longest edge / 8

bool large_enough(const ElementTree& tree, std::uint32_t element, double min_patch_size) {
    const double minimum =
        min_patch_size > 0.0 ? min_patch_size : tree.longest_edge(tree[element].base_patch) / kDefaultLevels;
    return tree.longest_edge(element) >= 2.0 * minimum * (1.0 - kSizeSlack);
}

// Keeps the `room` most important of `chosen` (area × request), then restores ascending order.
void keep_most_important(const ElementTree& tree, std::span<const std::uint32_t> elements,
                         const SplitRequests& requests, std::size_t room,
                         std::vector<std::uint32_t>& chosen) {
    const auto importance = [&](std::uint32_t i) {
        return tree[elements[i]].shape.area * std::max(requests.gradient[i], requests.shadow[i]);
    };
    std::stable_sort(chosen.begin(), chosen.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return importance(a) > importance(b); });
    chosen.resize(room);
    std::sort(chosen.begin(), chosen.end());
}

}  // namespace

SplitChoice choose_splits(const ElementTree& tree, std::span<const std::uint32_t> elements,
                          const SplitRequests& requests, double min_patch_size, std::size_t max_leaves) {
    SplitChoice choice;
    for (std::uint32_t i = 0; i < elements.size(); ++i) {
        const bool gradient = requests.gradient[i] >= 1.0, shadow = requests.shadow[i] >= 1.0;
        choice.gradient += gradient ? 1 : 0;
        choice.shadow += shadow ? 1 : 0;
        if (!gradient && !shadow) continue;
        if (large_enough(tree, elements[i], min_patch_size)) {
            choice.leaves.push_back(i);
        } else {
            ++choice.too_small;
        }
    }
    const std::size_t room = max_leaves > tree.leaf_count() ? (max_leaves - tree.leaf_count()) / 3 : 0;
    if (choice.leaves.size() > room) {
        choice.over_budget = true;
        keep_most_important(tree, elements, requests, room, choice.leaves);
    }
    return choice;
}

}  // namespace rad
