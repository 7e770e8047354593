#pragma once

// What the push-pull of hierarchical radiosity and its transpose share: irradiance at an element's corners,
// how a parent's corners interpolate to its children's, the exposed share, and the pull. Private to the
// library.
#include <algorithm>
#include <array>
#include <glm/vec3.hpp>
#include <vector>

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"

namespace rad {

// Irradiance at an element's corners (a triangle uses three).
using CornerIrradiance = std::array<glm::dvec3, 4>;

// The irradiance at the children's corners, interpolated from the parent's (ElementTree::split's layout).
inline std::array<CornerIrradiance, 4> child_corners(const CornerIrradiance& h, bool triangle) {
    const glm::dvec3 m01 = 0.5 * (h[0] + h[1]), m12 = 0.5 * (h[1] + h[2]);
    if (triangle) {
        const glm::dvec3 m20 = 0.5 * (h[2] + h[0]);
        return {{{h[0], m01, m20, m20}, {m01, h[1], m12, m12}, {m20, m12, h[2], h[2]}, {m01, m12, m20, m20}}};
    }
    const glm::dvec3 m23 = 0.5 * (h[2] + h[3]), m30 = 0.5 * (h[3] + h[0]);
    const glm::dvec3 centre = 0.25 * (h[0] + h[1] + h[2] + h[3]);
    return {{{h[0], m01, centre, m30},
             {m01, h[1], m12, centre},
             {centre, m12, h[2], m23},
             {m30, centre, m23, h[3]}}};
}

inline double exposed(const HierarchicalSystem& system, std::uint32_t e) {
    return std::max(0.0, static_cast<double>(system.exposed_share[e]));
}

// The factor a child's pushed irradiance is scaled by: the irradiance above is a mean over the whole parent,
// its covered part's zeros included; a child gets the exposed part's irradiance times its own exposed share.
inline double pushed_share(const HierarchicalSystem& system, std::uint32_t parent, std::uint32_t child) {
    const double parent_exposed = exposed(system, parent);
    return parent_exposed > 0.0 ? std::min(1.0 / parent_exposed, exposed(system, child) / parent_exposed)
                                : 0.0;
}

// Pull: every inner element's value becomes the area-weighted mean of its children's, the leaves' as they
// are in b (children come after their parents in the tree).
inline void pull_to_inner_elements(const HierarchicalSystem& system, std::vector<glm::dvec3>& b) {
    for (std::size_t e = b.size(); e-- > 0;) {
        const Element& element = system.tree[e];
        if (element.is_leaf()) continue;
        glm::dvec3 sum(0.0);
        double area = 0.0;
        for (std::uint32_t c = element.first_child; c < element.first_child + 4; ++c) {
            sum += system.tree[c].shape.area * b[c];
            area += system.tree[c].shape.area;
        }
        b[e] = area > 0.0 ? sum / area : glm::dvec3(0.0);
    }
}

}  // namespace rad
