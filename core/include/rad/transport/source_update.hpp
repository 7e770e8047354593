#pragma once

#include <cstdint>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/transport/transport.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// What the elements emit and reflect, again after the scene changed where form factors and links do not
// depend on it (the viewer's edits): they depend on the geometry alone and stay. `elements` are the
// transport's, in its order. Both throw std::invalid_argument when their number differs from the
// transport's.

// Each element's reflectance and emission from its surface's material. Elements of textured surfaces keep
// their reflectance (their texels' mean albedo). The sky's and sun's light on each element
// (Transport::outside) is reflected with the new reflectance.
void update_element_materials(Transport& transport, const PatchMesh& elements, const Scene& scene);

// The sky's and sun's light on each element measured again for the scene's sky and sun (cleared where it has
// neither), as building the transport measures it, and each element's emission with it. `element_rays` are
// over `elements`. Throws Cancelled when `progress` is cancelled, leaving the transport as it was.
void update_outside_light(Transport& transport, const PatchMesh& elements, const RayScene& element_rays,
                          const Scene& scene, std::uint64_t seed, Progress* progress = nullptr);

}  // namespace rad
