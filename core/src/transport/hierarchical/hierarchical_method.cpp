#include "transport/hierarchical/hierarchical_method.hpp"

namespace rad {

SceneTransport build_hierarchical_method(const Scene& scene, const PatchMesh& base,
                                         const TransportSettings& settings, Progress* progress) {
    // One memory budget, --max-memory, for the form factors and the links alike; its message counts
    // patches as the form factors' does.
    HierarchicalOptions options = settings.hierarchical;
    options.max_memory_bytes = settings.form_factors.max_memory_bytes;
    options.patch_size = settings.form_factors.patch_size;
    options.count_patches_at = settings.form_factors.count_patches_at;
    auto transport = make_hierarchical_transport(scene, base, options, progress);
    SceneTransport out;
    out.patches = &transport->system().leaf_patches;
    out.transport = std::move(transport);
    return out;
}

}  // namespace rad
