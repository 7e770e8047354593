#include "transport/clustered/clustered_method.hpp"

#include "rad/transport/clustered/clustered_transport.hpp"

namespace rad {

SceneTransport build_clustered_method(const Scene& scene, const PatchMesh& base,
                                      const TransportSettings& settings, Progress* progress) {
    ClusteredOptions options;
    if (settings.refine_tolerance > 0.0) options.tolerance = settings.refine_tolerance;
    options.min_patch_size = settings.min_patch_size;
    if (settings.form_factors.rays > 0) options.visibility_rays = settings.form_factors.rays;
    options.seed = settings.form_factors.seed;
    options.max_memory_bytes = settings.form_factors.max_memory_bytes;  // one budget, as for form factors
    auto transport = make_clustered_transport(scene, base, options, progress);
    SceneTransport out;
    out.patches = &transport->hierarchy().leaf_patches;
    out.transport = std::move(transport);
    return out;
}

}  // namespace rad
