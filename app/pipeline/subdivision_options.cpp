#include "pipeline/subdivision_options.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "cli/number_checks.hpp"
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

namespace {

std::vector<std::string> subdivision_name_list() {
    std::vector<std::string> names;
    for (Subdivision s : all_subdivisions()) names.emplace_back(subdivision_name(s));
    return names;
}

// The table's methods with what each does and the size of its first patches.
std::string subdivision_help() {
    std::string automatic;
    for (const TransportMethod& m : transport_methods()) {
        if (m.automatic_up_to == 0) continue;
        automatic += (automatic.empty() ? "" : ", ") + std::string(m.name) +
                     (m.automatic_up_to == kAnySize
                          ? " beyond"
                          : " up to " + std::to_string(m.automatic_up_to) + " patches at the uniform size");
    }
    std::string help = "How patches are made: auto (" + automatic + ")";
    for (const TransportMethod& m : transport_methods()) {
        help += ", " + std::string(m.name) + " (" + std::string(m.help);
        if (m.base_patch_scale != 1.0) {
            char scale[32];
            std::snprintf(scale, sizeof scale, "%g", m.base_patch_scale);
            help += std::string("; --patch-size is its first patches' size, by default ") + scale +
                    " times the uniform one";
        }
        help += ")";
    }
    return help;
}

}  // namespace

void add_subdivision_options(CLI::App& command, SubdivisionOptions& options) {
    command.add_option("--subdivision", options.method, subdivision_help())
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
