#include "transport/clustered/clustered_method.hpp"

namespace rad {

SceneTransport build_clustered_method(const Scene& scene, const PatchMesh& base,
                                      const TransportSettings& settings, Progress* progress) {
    ClusteredOptions options = settings.clustered;
    options.max_memory_bytes = settings.form_factors.max_memory_bytes;  // one budget, as for form factors
    auto transport = make_clustered_transport(scene, base, options, progress);
    SceneTransport out;
    out.patches = &transport->hierarchy().leaf_patches;
    out.transport = std::move(transport);
    return out;
}

}  // namespace rad
