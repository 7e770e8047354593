#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rad/scene/polygon_soup.hpp"

namespace rad {

// Faces cut where they enter closed solids, and the parts inside dropped. Modelling tools and IFC exporters
// build rooms of wall slabs that touch or run through each other, floors that run on under the walls, table
// legs through a floor: a patch that reaches into another solid takes light on one side of a wall and gives
// it out on the other. A solid is a set of faces joined along their edges (corners compared by position)
// that closes with every edge used once in each direction and encloses a positive volume (faces outwards).
// Every other face it meets is cut along the solid's faces that cross it (a plane crossing the face) or lie
// on it back to back (a wall standing on the floor), into convex pieces, and a piece whose front lies inside
// the solid is dropped, as is a face wholly inside one. Returns the soup with the cut faces replaced by their
// kept pieces (texture coordinates carried over), and nothing when no face is cut; adds one warning with the
// counts.
std::optional<PolygonSoup> cut_faces_at_solids(const PolygonSoup& soup, std::vector<std::string>& warnings);

}  // namespace rad
