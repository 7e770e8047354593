#include "rad/mesh/element_tree.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

namespace rad {

ElementTree::ElementTree(const PatchMesh& base)
    : points_(base.points),
      surface_begin_(base.surface_begin),
      back_to_back_(base.back_to_back),
      base_size_(base.size()),
      leaf_count_(base.size()) {
    if (base.size() >= Element::kNone / 8)
        throw std::length_error("too many base patches for an ElementTree");
    elements_.reserve(base.size());
    for (std::uint32_t q = 0; q < base.size(); ++q) {
        Element e;
        e.corners = base.corners[q];
        e.base_patch = q;
        e.shape = base.patches[q];
        elements_.push_back(e);
    }
}

std::uint32_t ElementTree::add_point(const glm::dvec3& p) {
    if (points_.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
        throw std::length_error("too many element corners");
    points_.push_back(p);
    return static_cast<std::uint32_t>(points_.size() - 1);
}

std::uint32_t ElementTree::midpoint(std::uint32_t a, std::uint32_t b) {
    const auto [it, added] = midpoints_.try_emplace(edge_key(a, b), 0u);
    if (added) it->second = add_point(0.5 * (points_[a] + points_[b]));
    return it->second;
}

void ElementTree::add_child(std::uint32_t parent, const glm::uvec4& corners) {
    const Element& p = elements_[parent];
    Element child;
    child.corners = corners;
    child.parent = parent;
    child.base_patch = p.base_patch;
    child.level = p.level + 1;
    child.shape = measure_patch(points_, corners, p.shape.surface, p.shape.normal);
    child.shape.face = p.shape.face;
    elements_.push_back(child);
}

std::uint32_t ElementTree::split(std::uint32_t element) {
    if (!elements_[element].is_leaf()) return elements_[element].first_child;
    if (elements_.size() + 4 >= Element::kNone) throw std::length_error("too many elements");
    const glm::uvec4 c = elements_[element].corners;
    const bool triangle = elements_[element].is_triangle();
    const std::uint32_t m01 = midpoint(c[0], c[1]), m12 = midpoint(c[1], c[2]);
    const auto first = static_cast<std::uint32_t>(elements_.size());
    if (triangle) {
        const std::uint32_t m20 = midpoint(c[2], c[0]);
        add_child(element, {c[0], m01, m20, m20});
        add_child(element, {m01, c[1], m12, m12});
        add_child(element, {m20, m12, c[2], c[2]});
        add_child(element, {m01, m12, m20, m20});
    } else {
        const std::uint32_t m23 = midpoint(c[2], c[3]), m30 = midpoint(c[3], c[0]);
        // The centre belongs to this element alone: no neighbour shares it.
        const std::uint32_t centre =
            add_point(0.25 * (points_[c[0]] + points_[c[1]] + points_[c[2]] + points_[c[3]]));
        add_child(element, {c[0], m01, centre, m30});
        add_child(element, {m01, c[1], m12, centre});
        add_child(element, {centre, m12, c[2], m23});
        add_child(element, {m30, centre, m23, c[3]});
    }
    elements_[element].first_child = first;
    leaf_count_ += 3;
    return first;
}

double ElementTree::longest_edge(std::uint32_t element) const {
    const Element& e = elements_[element];
    const int n = e.is_triangle() ? 3 : 4;
    double longest = 0.0;
    for (int k = 0; k < n; ++k)
        longest = std::max(longest, glm::length(points_[e.corners[(k + 1) % n]] - points_[e.corners[k]]));
    return longest;
}

std::vector<std::uint32_t> ElementTree::leaves() const {
    std::vector<std::uint32_t> out;
    out.reserve(leaf_count_);
    std::vector<std::uint32_t> stack;
    for (std::uint32_t b = 0; b < base_size_; ++b) {
        stack.push_back(b);
        while (!stack.empty()) {
            const std::uint32_t e = stack.back();
            stack.pop_back();
            if (elements_[e].is_leaf()) {
                out.push_back(e);
                continue;
            }
            for (std::uint32_t k = 4; k-- > 0;) stack.push_back(elements_[e].first_child + k);
        }
    }
    return out;
}

// The points strictly inside edge a -> b where neighbours split it, in order from a.
void ElementTree::append_edge_points(std::uint32_t a, std::uint32_t b,
                                     std::vector<std::uint32_t>& out) const {
    const auto it = midpoints_.find(edge_key(a, b));
    if (it == midpoints_.end()) return;
    append_edge_points(a, it->second, out);
    out.push_back(it->second);
    append_edge_points(it->second, b, out);
}

PatchMesh ElementTree::leaf_mesh(std::span<const std::uint32_t> leaves) const {
    PatchMesh mesh;
    mesh.points = points_;
    mesh.back_to_back = back_to_back_;
    mesh.positions.reserve(points_.size());
    for (const glm::dvec3& p : points_) mesh.positions.emplace_back(p);
    mesh.corners.reserve(leaves.size());
    mesh.patches.reserve(leaves.size());
    mesh.outline_begin.reserve(leaves.size() + 1);
    mesh.outline_begin.push_back(0);
    bool any_t_vertex = false;
    std::uint32_t surface = 0;
    mesh.surface_begin.push_back(0);
    for (std::size_t k = 0; k < leaves.size(); ++k) {
        const Element& e = elements_[leaves[k]];
        while (surface < e.shape.surface) {
            mesh.surface_begin.push_back(static_cast<std::uint32_t>(k));
            ++surface;
        }
        mesh.corners.push_back(e.corners);
        mesh.patches.push_back(e.shape);
        const int n = e.is_triangle() ? 3 : 4;
        const std::size_t before = mesh.outline.size();
        for (int c = 0; c < n; ++c) {
            mesh.outline.push_back(e.corners[c]);
            append_edge_points(e.corners[c], e.corners[(c + 1) % n], mesh.outline);
        }
        any_t_vertex = any_t_vertex || mesh.outline.size() - before > static_cast<std::size_t>(n);
        mesh.outline_begin.push_back(static_cast<std::uint32_t>(mesh.outline.size()));
    }
    const std::size_t surfaces = surface_begin_.empty() ? 0 : surface_begin_.size() - 1;
    while (mesh.surface_begin.size() < surfaces + 1)
        mesh.surface_begin.push_back(static_cast<std::uint32_t>(leaves.size()));
    if (!any_t_vertex) {
        mesh.outline_begin.clear();
        mesh.outline.clear();
    }
    return mesh;
}

std::size_t ElementTree::memory_bytes() const {
    return points_.capacity() * sizeof(glm::dvec3) + elements_.capacity() * sizeof(Element) +
           midpoints_.size() * (sizeof(std::uint64_t) + sizeof(std::uint32_t) + 2 * sizeof(void*)) +
           midpoints_.bucket_count() * sizeof(void*);
}

}  // namespace rad
