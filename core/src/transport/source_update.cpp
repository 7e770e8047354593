#include "rad/transport/source_update.hpp"

#include <stdexcept>

#include "rad/ray/ray_scene.hpp"
#include "transport/external/outside_light.hpp"

namespace rad {

namespace {

void check_elements(const Transport& transport, const PatchMesh& elements) {
    if (elements.size() != transport.size())
        throw std::invalid_argument("the elements given are not the transport's");
}

// E + ρ H_out, the equation's source term.
void set_emission(Transport& transport, const PatchMesh& elements, const Scene& scene) {
    for (std::size_t i = 0; i < transport.size(); ++i) {
        transport.emission[i] = scene.surfaces[elements.patches[i].surface].material.emitted_radiosity();
        if (!transport.outside.empty())
            transport.emission[i] += transport.reflectance[i] * transport.outside[i];
    }
}

}  // namespace

void update_element_materials(Transport& transport, const PatchMesh& elements, const Scene& scene) {
    check_elements(transport, elements);
    for (std::size_t i = 0; i < transport.size(); ++i) {
        const Material& material = scene.surfaces[elements.patches[i].surface].material;
        if (!material.texture) transport.reflectance[i] = material.reflectance;
    }
    set_emission(transport, elements, scene);
}

void update_outside_light(Transport& transport, const PatchMesh& elements, const RayScene& element_rays,
                          const Scene& scene, std::uint64_t seed, Progress* progress) {
    check_elements(transport, elements);
    if (has_outside_light(scene)) {
        transport.outside = outside_irradiance(scene, elements, element_rays, seed, transport.area, progress);
    } else {
        transport.outside.clear();
    }
    set_emission(transport, elements, scene);
}

}  // namespace rad
