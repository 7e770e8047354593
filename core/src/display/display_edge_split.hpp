#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rad/display/display_mesh.hpp"

namespace rad {

// An edge of a display mesh by its two vertices, in either order.
struct DisplayEdge {
    std::uint32_t a = 0, b = 0;
};

// The edges that two triangles share, each once (a < b), in the order the triangles first reach them. Only
// these can be split without a crack: an edge on one triangle alone is a surface's border or a crease (the
// next triangle has vertices of its own there), and a seam of another surface may run along it.
std::vector<DisplayEdge> interior_edges(const DisplayMesh& display);

// Splits each edge (an interior edge, listed once) at its midpoint, and both triangles on it with it, so the
// mesh stays conforming. A new vertex is the mean of its edge's ends in everything drawn with it (position,
// texture coordinate, and the weights of its patches, which is what the triangle showed there); its normal
// is the normalized mean. Triangles keep their order (a triangle's pieces take its place), their patch and
// their textured range. Returns the index of the first new vertex; they follow in the order of `edges`.
// display.direct must be empty (its vertex values are made after the split).
std::size_t split_display_edges(DisplayMesh& display, std::span<const DisplayEdge> edges);

}  // namespace rad
