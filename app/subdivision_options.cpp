#include "subdivision_options.hpp"

#include "rad/error.hpp"
#include "scene_options.hpp"

namespace rad {

std::string_view subdivision_name(Subdivision subdivision) {
    switch (subdivision) {
        case Subdivision::uniform:
            return "uniform";
        case Subdivision::hierarchical:
            return "hierarchical";
    }
    return "uniform";
}

Subdivision parse_subdivision(const std::string& name) {
    for (Subdivision s : {Subdivision::uniform, Subdivision::hierarchical})
        if (name == subdivision_name(s)) return s;
    throw InputError("--subdivision: unknown method '" + name + "' (uniform, hierarchical)");
}

void add_subdivision_options(CLI::App& command, SubdivisionOptions& options) {
    command
        .add_option("--subdivision", options.method,
                    "How patches are made: uniform (one size) or hierarchical (a quadtree of elements linked "
                    "where needed; --patch-size is then the base patch size, by default 4 times the uniform "
                    "one)")
        ->check(CLI::IsMember({"uniform", "hierarchical"}))
        ->capture_default_str();
    command
        .add_option("--refine-tol", options.tolerance,
                    "hierarchical: the error a link may leave in its receiver, relative to the scene's mean "
                    "radiosity (default 0.02)")
        ->check(positive_number());
    command
        .add_option("--min-patch-size", options.min_patch_size,
                    "hierarchical: elements are not split below this edge, in scene units (default: the "
                    "largest base patch edge / 64)")
        ->check(positive_number());
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
