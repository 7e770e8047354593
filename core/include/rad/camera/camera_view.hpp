#pragma once

#include <glm/mat4x4.hpp>

#include "rad/scene/scene.hpp"

namespace rad {

// A camera that frames the whole box, looking at its centre from the front (+z side), a little from above
// and the right, for scenes that bring no camera of their own.
Camera frame_bounding_box(const BoundingBox& box, double fov_degrees = 45.0);
// The same from another side: `towards_eye` points from the box's centre to the eye.
Camera frame_bounding_box(const BoundingBox& box, double fov_degrees, const glm::dvec3& towards_eye);

// From the box's centre towards the eye of the view frame_bounding_box frames the scene from: of the usual
// view and the same from the right, behind and the left (turned about +y), each also from the other side and
// straight on, the one whose eye sees the most area of surfaces from their front (lit) side and the least
// from behind. A room open on one side is seen through its opening, not through the back of its far wall.
// The usual view when no other shows clearly more (by 1 % of the scene's area), as for a closed room.
glm::dvec3 front_side(const Scene& scene, double fov_degrees = 45.0);

// The scene's own camera, or one that frames it from its front_side.
Camera scene_camera(const Scene& scene);

// Projection × view for an image of this aspect (width / height). Near and far planes are set from the
// scene's bounds so the depth buffer covers exactly what can be seen.
glm::mat4 view_projection(const Camera& camera, double aspect, const BoundingBox& scene_box);

}  // namespace rad
