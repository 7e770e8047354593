#include "transport/hierarchical/hierarchical_method.hpp"

#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"

namespace rad {

SceneTransport build_hierarchical_method(const Scene& scene, const PatchMesh& base,
                                         const TransportSettings& settings, Progress* progress) {
    // One memory budget, --max-memory, for the form factors and the links alike; its message counts
    // patches as the form factors' does.
    HierarchicalOptions options;
    if (settings.refine_tolerance > 0.0) options.tolerance = settings.refine_tolerance;
    options.min_patch_size = settings.min_patch_size;
    if (settings.form_factors.rays > 0) options.visibility_rays = settings.form_factors.rays;
    options.seed = settings.form_factors.seed;
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
