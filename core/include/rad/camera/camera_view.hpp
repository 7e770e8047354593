#pragma once

#include <glm/mat4x4.hpp>

#include "rad/scene/scene.hpp"

namespace rad {

// A camera that frames the whole box, looking at its centre from the front (+z side), a little from above
// and the right, for scenes that bring no camera of their own.
Camera frame_bounding_box(const BoundingBox& box, double fov_degrees = 45.0);

// The scene's own camera, or one that frames it.
Camera scene_camera(const Scene& scene);

// Projection × view for an image of this aspect (width / height). Near and far planes are set from the
// scene's bounds so the depth buffer covers exactly what can be seen.
glm::mat4 view_projection(const Camera& camera, double aspect, const BoundingBox& scene_box);

}  // namespace rad
