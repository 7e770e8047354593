#include "rad/transport/transport_methods.hpp"

#include <algorithm>
#include <stdexcept>

#include "transport/adaptive/adaptive_method.hpp"
#include "transport/clustered/clustered_method.hpp"
#include "transport/hierarchical/hierarchical_method.hpp"
#include "transport/uniform/uniform_method.hpp"

namespace rad {

namespace {

// Adaptive subdivision starts from patches twice the uniform size and splits them where the light needs it.
constexpr double kAdaptiveBaseScale = 2.0;
// Every pair of a hierarchy's base patches gets a link, so they are few: 4 × the uniform size; the hierarchy
// refines them.
constexpr double kHierarchyBaseScale = 4.0;
// Hierarchical radiosity links every pair of base patches first: past this many, minutes.
constexpr std::size_t kHierarchicalPracticalBasePatches = 5'000;

// The refinement tolerances the bench compares, coarse to fine, around each method's default (adaptive 0.15,
// hierarchical 0.02, clustered 0.05).
constexpr double kAdaptiveTolerances[] = {0.25, 0.15};
constexpr double kHierarchicalTolerances[] = {0.1, 0.03, 0.01, 0.003};
constexpr double kClusteredTolerances[] = {0.2, 0.1, 0.05, 0.02};

const TransportMethod kMethods[] = {
    {.id = Subdivision::uniform,
     .name = "uniform",
     .help = "one size, form factors between every pair of patches",
     .has_matrix = true,
     .automatic_up_to = kAutomaticUniformPatches,
     .build = build_uniform_method},
    {.id = Subdivision::adaptive,
     .name = "adaptive",
     .help = "split where the light changes, then solved again",
     .base_patch_scale = kAdaptiveBaseScale,
     .has_matrix = true,
     .refine_tolerances = kAdaptiveTolerances,
     .quick_refine_tolerance = 0.5,
     .build = build_adaptive_method},
    {.id = Subdivision::hierarchical,
     .name = "hierarchical",
     .help = "a quadtree of elements over base patches, linked where needed",
     .base_patch_scale = kHierarchyBaseScale,
     .drawn_on_uniform_patches = true,
     .practical_base_patches = kHierarchicalPracticalBasePatches,
     .refine_tolerances = kHierarchicalTolerances,
     .quick_refine_tolerance = 0.05,
     .build = build_hierarchical_method},
    {.id = Subdivision::clustered,
     .name = "clustered",
     .help = "hierarchical with volume clusters over the base patches, for scenes of many faces",
     .base_patch_scale = kHierarchyBaseScale,
     .drawn_on_uniform_patches = true,
     .automatic_up_to = kAnySize,
     .refine_tolerances = kClusteredTolerances,
     .quick_refine_tolerance = 0.1,
     .build = build_clustered_method},
};

}  // namespace

std::span<const TransportMethod> transport_methods() {
    return kMethods;
}

const TransportMethod& transport_method(Subdivision id) {
    for (const TransportMethod& m : kMethods)
        if (m.id == id) return m;
    throw std::logic_error("transport_method: automatic is no method; choose one first");
}

const TransportMethod* find_transport_method(std::string_view name) {
    for (const TransportMethod& m : kMethods)
        if (m.name == name) return &m;
    return nullptr;
}

const TransportMethod& automatic_transport_method(std::size_t uniform_patches) {
    for (const TransportMethod& m : kMethods)
        if (uniform_patches <= m.automatic_up_to) return m;
    return kMethods[std::size(kMethods) - 1];
}

std::string_view subdivision_name(Subdivision subdivision) {
    return subdivision == Subdivision::automatic ? "auto" : transport_method(subdivision).name;
}

const std::vector<Subdivision>& all_subdivisions() {
    static const std::vector<Subdivision> all = [] {
        std::vector<Subdivision> out{Subdivision::automatic};
        for (const TransportMethod& m : kMethods) out.push_back(m.id);
        return out;
    }();
    return all;
}

Subdivision choose_subdivision(Subdivision requested, std::size_t uniform_patches) {
    return requested != Subdivision::automatic ? requested : automatic_transport_method(uniform_patches).id;
}

bool has_matrix(Subdivision subdivision) {
    return subdivision != Subdivision::automatic && transport_method(subdivision).has_matrix;
}

}  // namespace rad
