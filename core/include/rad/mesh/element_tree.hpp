#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <unordered_map>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// One node of an ElementTree: a base patch, or a quarter of its parent.
struct Element {
    static constexpr std::uint32_t kNone = 0xffffffffu;
    glm::uvec4 corners{0};  // into ElementTree::points; a triangle repeats its last corner
    std::uint32_t parent = kNone;
    std::uint32_t first_child = kNone;  // its four children are first_child .. first_child + 3
    std::uint32_t base_patch = 0;       // the base patch it lies in
    std::uint32_t level = 0;            // 0 for a base patch
    Patch shape;                        // surface, area, centroid, normal

    bool is_leaf() const { return first_child == kNone; }
    bool is_triangle() const { return corners[3] == corners[2]; }
};

// Base patches cut into quarters as often as wanted, for adaptive subdivision and hierarchical radiosity. A
// quad splits at its edge midpoints and centre into four quads, a triangle at its edge midpoints into four
// triangles. Two elements sharing an edge share its midpoint when both split, so the leaves, though of
// different sizes, meet without gaps; leaf_mesh lists where a small leaf's corner lies on a larger leaf's
// edge (a T-vertex) so the display can stay free of cracks.
class ElementTree {
  public:
    // Elements 0 .. base.size() - 1 are the base patches, in order. Within a surface the base mesh must be
    // conforming (build_patches makes it so).
    explicit ElementTree(const PatchMesh& base);

    // Splits a leaf into four and returns its first child; for an element already split, returns its first
    // child. Invalidates references to elements.
    std::uint32_t split(std::uint32_t element);

    std::size_t size() const { return elements_.size(); }
    std::size_t base_size() const { return base_size_; }
    const Element& operator[](std::size_t e) const { return elements_[e]; }
    const std::vector<glm::dvec3>& points() const { return points_; }
    // The longest edge of an element.
    double longest_edge(std::uint32_t element) const;

    // Every leaf, base patch by base patch, depth first.
    std::vector<std::uint32_t> leaves() const;
    std::size_t leaf_count() const { return leaf_count_; }

    // The given leaves as patches (patch k is leaves[k]), with outlines where T-vertices lie on their edges.
    // The leaves must cover the base patches exactly, as leaves() does.
    PatchMesh leaf_mesh(std::span<const std::uint32_t> leaves) const;

    std::size_t memory_bytes() const;

  private:
    std::uint32_t midpoint(std::uint32_t a, std::uint32_t b);
    std::uint32_t add_point(const glm::dvec3& p);
    void add_child(std::uint32_t parent, const glm::uvec4& corners);
    void append_edge_points(std::uint32_t a, std::uint32_t b, std::vector<std::uint32_t>& out) const;

    static std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
        return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
    }

    std::vector<glm::dvec3> points_;
    std::vector<Element> elements_;
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints_;  // edge (two points) -> its midpoint
    std::vector<std::uint32_t> surface_begin_;
    std::vector<std::uint8_t> back_to_back_;  // per surface, as PatchMesh::back_to_back
    std::size_t base_size_ = 0;
    std::size_t leaf_count_ = 0;
};

}  // namespace rad
