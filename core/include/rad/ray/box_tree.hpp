#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace rad {

struct Box {
    glm::dvec3 lower{0.0};
    glm::dvec3 upper{0.0};
};

// A bounding-volume hierarchy over boxes (Embree's SAH builder, behind the ray interface): node 0 is the
// root; an inner node has children [first, first + count) in `nodes`, a leaf holds items
// [first, first + count) of `items` (indices into the boxes). Nodes are in depth-first order, children after
// their parent, so every node's items form one contiguous range of `items`: [item_begin, item_end).
struct BoxTree {
    struct Node {
        Box bounds;
        std::uint32_t first = 0;
        std::uint32_t count = 0;
        std::uint32_t item_begin = 0;
        std::uint32_t item_end = 0;
        bool leaf = true;
    };
    std::vector<Node> nodes;
    std::vector<std::uint32_t> items;
};

// The same boxes always give the same tree, whatever the number of threads.
BoxTree build_box_tree(std::span<const Box> boxes, unsigned max_leaf_size);

}  // namespace rad
