#include "viewer/scene_materials.hpp"

#include <algorithm>
#include <cstddef>

namespace rad {

std::shared_ptr<const std::vector<ViewerMaterial>> scene_materials(const Scene& scene) {
    auto materials = std::make_shared<std::vector<ViewerMaterial>>();
    for (const Surface& surface : scene.surfaces) {
        const Material& m = surface.material;
        auto found = std::find_if(materials->begin(), materials->end(),
                                  [&](const ViewerMaterial& v) { return v.name == m.name; });
        if (found == materials->end()) {
            materials->push_back({m.name, m.reflectance, m.emission, m.texture != nullptr, 0.0});
            found = materials->end() - 1;
        }
        found->area += surface_area(surface.mesh);
    }
    return materials;
}

std::vector<std::uint32_t> triangle_materials(const Scene& scene,
                                              const std::vector<ViewerMaterial>& materials,
                                              const DisplayMesh& display) {
    std::vector<std::uint32_t> of_surface(scene.surfaces.size(), 0);
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const auto found = std::find_if(materials.begin(), materials.end(), [&](const ViewerMaterial& v) {
            return v.name == scene.surfaces[s].material.name;
        });
        of_surface[s] = static_cast<std::uint32_t>(found - materials.begin());
    }
    std::vector<std::uint32_t> triangle(display.triangle_patch.size());
    for (std::size_t t = 0; t < triangle.size(); ++t)
        triangle[t] = of_surface[display.patch_surface[display.triangle_patch[t]]];
    return triangle;
}

}  // namespace rad
