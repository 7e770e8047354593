#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// Each patch's mean albedo: its material's reflectance, or on a textured surface the mean of the texture's
// albedo over the patch (sampled at kPatchAlbedoSamples² points spread over it), so a patch on the dark
// half of an image reflects less than one on the light half while the surface as a whole reflects its
// material's reflectance.
inline constexpr int kPatchAlbedoSamples = 4;
std::vector<glm::dvec3> patch_albedo(const Scene& scene, const PatchMesh& patches);

}  // namespace rad
