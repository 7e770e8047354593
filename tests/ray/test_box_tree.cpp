// The bounding-volume hierarchy of boxes (Embree's builder): every box in exactly one leaf, every node's
// bounds holding its children's and its items', contiguous item ranges, and the same tree every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/common.hpp>
#include <random>

#include "rad/ray/box_tree.hpp"

namespace rad {
namespace {

std::vector<Box> random_boxes(std::size_t n) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> position(-10.0, 10.0), size(0.0, 1.0);
    std::vector<Box> boxes(n);
    for (Box& b : boxes) {
        b.lower = glm::dvec3(position(random), position(random), position(random));
        b.upper = b.lower + glm::dvec3(size(random), size(random), size(random));
    }
    return boxes;
}

bool holds(const Box& outer, const Box& inner) {
    constexpr double slack = 1e-5;  // Embree works in float
    return glm::all(glm::lessThanEqual(outer.lower, inner.lower + slack)) &&
           glm::all(glm::greaterThanEqual(outer.upper, inner.upper - slack));
}

TEST(BoxTree, EveryBoxInOneLeafWithinItsNodesBounds) {
    const std::vector<Box> boxes = random_boxes(5000);
    const BoxTree tree = build_box_tree(boxes, 4);
    ASSERT_EQ(tree.items.size(), boxes.size());
    std::vector<int> seen(boxes.size(), 0);
    for (std::uint32_t item : tree.items) ++seen[item];
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        const BoxTree::Node& node = tree.nodes[n];
        ASSERT_LT(node.item_begin, node.item_end) << "node " << n;
        for (std::uint32_t k = node.item_begin; k < node.item_end; ++k)
            ASSERT_TRUE(holds(node.bounds, boxes[tree.items[k]])) << "node " << n;
        if (node.leaf) {
            EXPECT_LE(node.count, 4u);
            EXPECT_EQ(node.first, node.item_begin);
            EXPECT_EQ(node.item_end - node.item_begin, node.count);
            continue;
        }
        ASSERT_GT(node.first, n);  // children after their parent
        std::uint32_t at = node.item_begin;
        for (std::uint32_t c = node.first; c < node.first + node.count; ++c) {
            EXPECT_TRUE(holds(node.bounds, tree.nodes[c].bounds));
            EXPECT_EQ(tree.nodes[c].item_begin, at);  // the children split the parent's range in order
            at = tree.nodes[c].item_end;
        }
        EXPECT_EQ(at, node.item_end);
    }
}

TEST(BoxTree, TheSameBoxesGiveTheSameTree) {
    const std::vector<Box> boxes = random_boxes(3000);
    const BoxTree a = build_box_tree(boxes, 4), b = build_box_tree(boxes, 4);
    EXPECT_EQ(a.items, b.items);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t n = 0; n < a.nodes.size(); ++n) EXPECT_EQ(a.nodes[n].first, b.nodes[n].first);
}

TEST(BoxTree, OneBoxIsARootLeaf) {
    const std::vector<Box> boxes = random_boxes(1);
    const BoxTree tree = build_box_tree(boxes, 4);
    ASSERT_EQ(tree.nodes.size(), 1u);
    EXPECT_TRUE(tree.nodes[0].leaf);
    EXPECT_EQ(tree.items, std::vector<std::uint32_t>{0});
}

}  // namespace
}  // namespace rad
