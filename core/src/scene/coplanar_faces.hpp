#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rad/scene/polygon_soup.hpp"

namespace rad {

// How far a covering face is moved, as a share of the scene's bounding-box diagonal: far enough for the
// depth buffer to tell it from the surface behind (a 32-bit float depth buffer resolves about 6e-4 of the
// diagonal at the far end of the scene when the eye is inside it) and for rays leaving that surface to meet
// the emitter's back, small enough to change no visible geometry.
inline constexpr double kCoplanarLift = 1e-3;

// Two polygons of different surfaces that lie in one plane (within 1e-6 of the scene's diagonal), face the
// same way and overlap with positive area, as the published Cornell box's light lies in its ceiling or a rug
// in a floor, tie: rays and the depth buffer pick either, leaving speckles, and the light arriving there is
// split between the two. The covering one is moved kCoplanarLift of the scene's diagonal along its normal,
// in front of the other, so that it is what is seen and hit there and the covered part behind it receives
// no light. The covering one is the emitter where one of the two surfaces emits, else the surface of the
// smaller area (the rug, not the floor). Moved faces of one surface keep their shared corners; a face of
// that surface left in place is no longer joined to them. Returns the soup with those polygons moved, and
// nothing when no polygon moves; adds one warning per pair of surfaces.
std::optional<PolygonSoup> lift_coplanar_faces(const PolygonSoup& soup, std::vector<std::string>& warnings);

}  // namespace rad
