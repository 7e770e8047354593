#pragma once

// How far rays start off the surface they leave. Private to the library: every stage that traces rays from
// surfaces (form factors, links, the display's gathers, the path tracer) uses this one offset.

#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// Rays start off their patch, along its normal, so that they do not hit the patch they leave: Embree works in
// float. The offset is the larger of kRayOffsetFraction of the scene's bounding-box diagonal and
// kRayOffsetUlps float steps of the scene's largest coordinate (for a scene far from the origin, where float
// steps are coarse). Surfaces that face each other closer than the offset do not see each other, so it is
// kept small: 3.8e-6 of the size of a unit cube at the origin, which plates 1e-5 apart still resolve.
inline constexpr double kRayOffsetFraction = 2e-6;
inline constexpr double kRayOffsetUlps = 32.0;

double ray_offset(const PatchMesh& patches);

}  // namespace rad
