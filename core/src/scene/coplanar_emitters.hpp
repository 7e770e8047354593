#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rad/scene/polygon_soup.hpp"

namespace rad {

// How far a covering emitter is moved, as a share of the scene's bounding-box diagonal: far enough for the
// depth buffer to tell it from the surface behind (a 32-bit float depth buffer resolves about 6e-4 of the
// diagonal at the far end of the scene when the eye is inside it) and for rays leaving that surface to meet
// the emitter's back, small enough to change no visible geometry.
inline constexpr double kCoplanarEmitterLift = 1e-3;

// An emitting polygon that lies in the plane of a non-emitting one (within 1e-6 of the scene's diagonal),
// faces the same way and overlaps it with positive area, as the published Cornell box's light lies in its
// ceiling, would tie with it: rays and the depth buffer would pick either, leaving blotches, and the light
// arriving there would be split between the two. Such a polygon is moved kCoplanarEmitterLift of the
// scene's diagonal along its normal, in front of the surface it covers, so that the emitter is what is seen
// and hit there and the covered part of the other surface, behind it, receives no light. Faces of the same
// emitting surface that are moved keep their shared corners; a face of that surface left in place is no
// longer joined to them. Returns the soup with those polygons moved, and nothing when no polygon moves;
// adds one warning per pair of surfaces.
std::optional<PolygonSoup> lift_coplanar_emitters(const PolygonSoup& soup,
                                                  std::vector<std::string>& warnings);

}  // namespace rad
