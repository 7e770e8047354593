#pragma once

// Closing the seams where surfaces meet. Private to the library.

#include "rad/display/display_mesh.hpp"

namespace rad {

// Where a corner of one surface's triangles lies inside an edge of another's (a T-vertex across surfaces,
// which the patches' own outlines do not list: surfaces share no corners), the two edges are not drawn
// with the same end points, and rasterization leaves crack pixels along the seam. Each triangle with such
// points on its edges is redrawn as a fan from its centroid through its corners and those points, whose
// new vertices take the colour the edge had there (weights interpolated along the edge, as are texture
// coordinates), so the image is unchanged but for the cracks. Edges are matched by position, within a
// millionth of the mesh's size. Vertices and triangles keep their order, the new ones following each
// triangle in place, so runs of triangles stay runs.
void close_seams(DisplayMesh& display);

}  // namespace rad
