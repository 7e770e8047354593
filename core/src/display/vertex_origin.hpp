#pragma once

// Where a display vertex's rays leave from. Private to the library.

#include <cstddef>
#include <glm/vec3.hpp>

#include "rad/display/display_mesh.hpp"

namespace rad {

// Vertex v's position moved a thousandth of the way towards the centroid of the patches it shows, within its
// tangent plane, so a vertex on an edge is not in the plane of the surface beyond.
glm::dvec3 vertex_origin(const DisplayMesh& display, const PatchMesh& patches, std::size_t v);

}  // namespace rad
