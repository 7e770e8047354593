#include "pipeline/subdivision_options.hpp"

#include <string>
#include <vector>

#include "cli/number_checks.hpp"
#include "pipeline/scene_options.hpp"
#include "rad/util/error.hpp"

namespace rad {

double base_patch_scale(Subdivision subdivision) {
    switch (subdivision) {
        case Subdivision::adaptive:
            return kAdaptiveBaseScale;
        case Subdivision::hierarchical:
        case Subdivision::clustered:
            return kHierarchicalBaseScale;
        case Subdivision::automatic:  // meshed as uniform first (choose_subdivision)
        case Subdivision::uniform:
            break;
    }
    return 1.0;
}

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

namespace {

std::vector<std::string> subdivision_name_list() {
    std::vector<std::string> names;
    for (Subdivision s : all_subdivisions()) names.emplace_back(subdivision_name(s));
    return names;
}

}  // namespace

void add_subdivision_options(CLI::App& command, SubdivisionOptions& options) {
    command
        .add_option(
            "--subdivision", options.method,
            "How patches are made: auto (uniform up to " + std::to_string(kAutomaticUniformPatches) +
                " patches at the uniform size, clustered beyond), uniform (one size), adaptive (split where "
                "the light changes, then "
                "solved again; --patch-size is the first size, by default twice the uniform one), "
                "hierarchical (a quadtree of elements linked where needed; --patch-size is the base "
                "patch size, by default 4 times the uniform one) or clustered (hierarchical with volume "
                "clusters over the base patches, for scenes of many faces; base patches as hierarchical)")
        ->check(CLI::IsMember(subdivision_name_list()))
        ->capture_default_str();
    command
        .add_option("--refine-tol", options.tolerance,
                    "adaptive: the relative step between neighbours that splits them (default 0.15); "
                    "hierarchical and clustered: the error a link may leave in its receiver, relative to the "
                    "scene's mean radiosity (default: hierarchical 0.02, clustered 0.05)")
        ->check(positive_number());
    command
        .add_option(
            "--min-patch-size", options.min_patch_size,
            "adaptive, hierarchical and clustered: patches are not split below this edge, in scene "
            "units (default: adaptive, each first patch's longest edge / 8; hierarchical, the largest "
            "base patch edge / 64; clustered, the scene's largest extent / 64)")
        ->check(positive_number());
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
