#pragma once

// Each base patch's reflectance and emitted radiosity, from its surface's material: where the element trees
// of hierarchical radiosity and clustering start. Private to the library.

#include <glm/vec3.hpp>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

inline void append_patch_materials(const Scene& scene, const PatchMesh& patches,
                                   std::vector<glm::dvec3>& reflectance, std::vector<glm::dvec3>& emission) {
    for (const Patch& p : patches.patches) {
        const Material& material = scene.surfaces[p.surface].material;
        reflectance.push_back(material.reflectance);
        emission.push_back(material.emitted_radiosity());
    }
}

}  // namespace rad
