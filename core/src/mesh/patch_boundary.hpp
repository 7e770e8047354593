#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/gtc/type_ptr.hpp>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// The points on patch q's boundary, counter-clockwise: its outline where the mesh has outlines (corners
// and T-vertices), else its corners.
inline std::span<const std::uint32_t> patch_boundary(const PatchMesh& mesh, std::size_t q) {
    if (mesh.outline_begin.empty())
        return {glm::value_ptr(mesh.corners[q]), static_cast<std::size_t>(mesh.corner_count(q))};
    return {mesh.outline.data() + mesh.outline_begin[q], mesh.outline_begin[q + 1] - mesh.outline_begin[q]};
}

// The patches whose boundary passes through each point, as compressed rows: point p's are
// [begin[p], begin[p + 1]), in increasing order. Through a T-vertex that is the smaller patches it is a
// corner of and the larger one whose edge it lies on.
struct PointPatches {
    std::vector<std::uint32_t> begin;
    std::vector<std::uint32_t> patch;

    std::span<const std::uint32_t> at(std::uint32_t point) const {
        return {patch.data() + begin[point], begin[point + 1] - begin[point]};
    }
};

PointPatches patches_at_points(const PatchMesh& mesh);

}  // namespace rad
