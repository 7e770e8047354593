#pragma once

#include <vector>

#include "rad/scene/material.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "scene/gltf/gltf_file.hpp"
#include "scene/gltf/gltf_nodes.hpp"

namespace rad {

// Adds the triangles of every placed node's mesh to `soup`, in world coordinates: one group per (mesh,
// material) pair, named after the mesh (and the material, when the mesh has several); pairs of triangles that
// make a planar convex quad become that quad (merge_triangle_pairs). Triangle strips and
// fans become triangles; points and lines are skipped, counted in one warning. Refuses (InputError) what
// cannot be read: a missing mesh or POSITION, accessors that do not fit, indices out of range, positions
// beyond kMaxCoordinate, and more vertices or faces than the scene file limits.
void add_meshes(GltfFile& file, const std::vector<PlacedNode>& nodes, const std::vector<Material>& materials,
                PolygonSoup& soup);

}  // namespace rad
