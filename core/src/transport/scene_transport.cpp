#include "rad/transport/scene_transport.hpp"

#include "rad/transport/source_update.hpp"
#include "transport/external/outside_light.hpp"

namespace rad {

SceneTransport build_scene_transport(const Scene& scene, const PatchMesh& base,
                                     const TransportSettings& settings, Progress* progress) {
    const TransportMethod& method = transport_method(choose_subdivision(settings.subdivision, base.size()));
    SceneTransport out = method.build(scene, base, settings, progress);
    out.method = &method;
    // The sky's and sun's light on each element, measured on the elements themselves (hierarchies refine
    // below their base patches, where a shadow's edge may run), as a source beside the emitters' E.
    if (has_outside_light(scene)) {
        out.element_rays = std::make_shared<const RayScene>(*out.patches);
        update_outside_light(*out.transport, *out.patches, *out.element_rays, scene,
                             settings.form_factors.seed, progress);
    }
    return out;
}

}  // namespace rad
