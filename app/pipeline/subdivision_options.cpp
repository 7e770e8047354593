#include "pipeline/subdivision_options.hpp"

#include <string>
#include <vector>

#include "pipeline/scene_options.hpp"
#include "rad/util/error.hpp"

namespace rad {

std::string subdivision_names(const std::string& separator) {
    std::string names;
    for (Subdivision s : all_subdivisions())
        names += (names.empty() ? "" : separator) + std::string(subdivision_name(s));
    return names;
}

Subdivision parse_subdivision(const std::string& name) {
    for (Subdivision s : all_subdivisions())
        if (name == subdivision_name(s)) return s;
    throw InputError("--subdivision: unknown method '" + name + "' (" + subdivision_names(", ") + ")");
}

AdaptiveOptions adaptive_options(const SubdivisionOptions& options, std::uint64_t seed) {
    AdaptiveOptions a;
    a.tolerance = options.tolerance > 0.0 ? options.tolerance : 0.15;
    a.min_patch_size = options.min_patch_size;
    a.seed = seed;
    return a;
}

ClusteredOptions clustered_options(const SubdivisionOptions& options, int rays, std::uint64_t seed) {
    ClusteredOptions c;
    if (options.tolerance > 0.0) c.tolerance = options.tolerance;
    c.min_patch_size = options.min_patch_size;
    if (rays > 0) c.visibility_rays = rays;
    c.seed = seed;
    return c;
}

HierarchicalOptions hierarchical_options(const SubdivisionOptions& options, int rays, std::uint64_t seed) {
    HierarchicalOptions h;
    if (options.tolerance > 0.0) h.tolerance = options.tolerance;
    h.min_patch_size = options.min_patch_size;
    h.visibility_rays = rays;
    h.seed = seed;
    return h;
}

}  // namespace rad
