#pragma once

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/transport/transport.hpp"

namespace rad {

// After materials of `scene` changed (the viewer's edits): each element's reflectance and emission from its
// surface's material again, every form factor or link kept, as they depend on the geometry alone. Elements of
// textured surfaces keep their reflectance (their texels' mean albedo). The sky's and sun's light on each
// element (Transport::outside) is reflected with the new reflectance. `elements` are the transport's, in its
// order. Throws std::invalid_argument when their number differs from the transport's.
void update_element_materials(Transport& transport, const PatchMesh& elements, const Scene& scene);

}  // namespace rad
