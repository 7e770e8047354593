#pragma once

// Each base patch's reflectance (its mean albedo, for a textured surface) and emitted radiosity, from its
// surface's material: where the element trees of hierarchical radiosity and clustering start. Private to the
// library.

#include <glm/vec3.hpp>
#include <vector>

#include "rad/mesh/patch_albedo.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

inline void append_patch_materials(const Scene& scene, const PatchMesh& patches,
                                   std::vector<glm::dvec3>& reflectance, std::vector<glm::dvec3>& emission) {
    const std::vector<glm::dvec3> albedo = patch_albedo(scene, patches);
    reflectance.insert(reflectance.end(), albedo.begin(), albedo.end());
    for (const Patch& p : patches.patches)
        emission.push_back(scene.surfaces[p.surface].material.emitted_radiosity());
}

}  // namespace rad
