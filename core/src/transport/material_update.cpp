#include "rad/transport/material_update.hpp"

#include <stdexcept>

namespace rad {

void update_element_materials(Transport& transport, const PatchMesh& elements, const Scene& scene) {
    if (elements.size() != transport.size())
        throw std::invalid_argument("update_element_materials: the elements are not the transport's");
    for (std::size_t i = 0; i < transport.size(); ++i) {
        const Material& material = scene.surfaces[elements.patches[i].surface].material;
        if (!material.texture) transport.reflectance[i] = material.reflectance;
        transport.emission[i] = material.emitted_radiosity();
        if (!transport.outside.empty())
            transport.emission[i] += transport.reflectance[i] * transport.outside[i];
    }
}

}  // namespace rad
