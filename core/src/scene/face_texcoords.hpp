#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "rad/scene/scene.hpp"

namespace rad {

// Whether the surface's faces carry texture coordinates (and its material a texture to apply them to).
bool is_textured(const Surface& surface);

// The texture coordinates at `point`, on or inside the planar convex face `face`, interpolated from its
// corners' by mean value coordinates (Floater 2003): barycentric on a triangle, exact for any affine map on
// any polygon, and continuous across the edge two faces share. NaN where the face has none.
glm::dvec2 texcoord_at(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face, const glm::dvec3& point);

}  // namespace rad
