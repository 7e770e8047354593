#include "rad/transport/scene_transport.hpp"

#include <string>

#include "rad/ray/ray_scene.hpp"
#include "rad/transport/source_update.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "transport/external/outside_light.hpp"

namespace rad {

namespace {

SceneTransport uniform(const Scene& scene, const PatchMesh& base, const TransportSettings& settings,
                       Progress* progress) {
    FormFactorReport report;
    FormFactorMatrix form_factors = compute_form_factors(base, settings.form_factors, &report, progress);
    SceneTransport out;
    out.transport = std::make_unique<UniformTransport>(
        make_uniform_transport(scene, base, std::move(form_factors), report));
    out.patches = &base;
    return out;
}

std::string pass_sizes(const AdaptiveReport& report) {
    std::string sizes;
    for (const AdaptivePass& p : report.passes)
        sizes += (sizes.empty() ? "" : " -> ") + std::to_string(p.patches);
    return sizes;
}

SceneTransport adaptive(const Scene& scene, const PatchMesh& base, const TransportSettings& settings,
                        Progress* progress) {
    AdaptiveResult result = subdivide_adaptively(scene, base, settings.form_factors, settings.pass_method,
                                                 settings.pass_solver, settings.adaptive, progress);
    const AdaptiveReport& a = result.report;
    auto transport = std::make_unique<UniformTransport>(std::move(result.system));
    transport->kind = "adaptive";
    transport->form_factor_passes = a.passes.size();
    transport->form_factor_report.seconds = a.seconds;  // every pass, not only the last one's form factors
    transport->details = {{"passes", static_cast<double>(a.passes.size())},
                          {"shadow_sources", static_cast<double>(a.shadow_sources)}};
    transport->notes = std::to_string(a.passes.size()) + " passes (" + pass_sizes(a) +
                       " patches), stopped: " + std::string(adaptive_stop_name(a.stop));
    SceneTransport out;
    out.transport = std::move(transport);
    out.refined_patches = std::make_unique<const PatchMesh>(std::move(result.patches));
    out.patches = out.refined_patches.get();
    return out;
}

// A hierarchy's transport and its leaves, which it holds.
SceneTransport with_leaves(std::unique_ptr<Transport> transport, const PatchMesh& leaves) {
    SceneTransport out;
    out.patches = &leaves;
    out.transport = std::move(transport);
    return out;
}

SceneTransport hierarchical(const Scene& scene, const PatchMesh& base, const TransportSettings& settings,
                            Progress* progress) {
    auto transport = make_hierarchical_transport(scene, base, settings.hierarchical, progress);
    const PatchMesh& leaves = transport->system().leaf_patches;
    return with_leaves(std::move(transport), leaves);
}

SceneTransport clustered(const Scene& scene, const PatchMesh& base, const TransportSettings& settings,
                         Progress* progress) {
    auto transport = make_clustered_transport(scene, base, settings.clustered, progress);
    const PatchMesh& leaves = transport->hierarchy().leaf_patches;
    return with_leaves(std::move(transport), leaves);
}

}  // namespace

std::string_view subdivision_name(Subdivision subdivision) {
    switch (subdivision) {
        case Subdivision::automatic:
            return "auto";
        case Subdivision::uniform:
            return "uniform";
        case Subdivision::adaptive:
            return "adaptive";
        case Subdivision::hierarchical:
            return "hierarchical";
        case Subdivision::clustered:
            return "clustered";
    }
    return "uniform";
}

const std::vector<Subdivision>& all_subdivisions() {
    static const std::vector<Subdivision> all = {Subdivision::automatic, Subdivision::uniform,
                                                 Subdivision::adaptive, Subdivision::hierarchical,
                                                 Subdivision::clustered};
    return all;
}

Subdivision choose_subdivision(Subdivision requested, std::size_t uniform_patches) {
    if (requested != Subdivision::automatic) return requested;
    return uniform_patches <= kAutomaticUniformPatches ? Subdivision::uniform : Subdivision::clustered;
}

bool has_matrix(Subdivision subdivision) {
    return subdivision == Subdivision::uniform || subdivision == Subdivision::adaptive;
}

namespace {

SceneTransport build_transport(const Scene& scene, const PatchMesh& base, const TransportSettings& settings,
                               Progress* progress) {
    switch (choose_subdivision(settings.subdivision, base.size())) {
        case Subdivision::adaptive:
            return adaptive(scene, base, settings, progress);
        case Subdivision::hierarchical:
            return hierarchical(scene, base, settings, progress);
        case Subdivision::clustered:
            return clustered(scene, base, settings, progress);
        case Subdivision::automatic:
        case Subdivision::uniform:
            break;
    }
    return uniform(scene, base, settings, progress);
}

// The sky's and sun's light on each element, measured on the elements themselves (hierarchies refine below
// their base patches, where a shadow's edge may run), as a source beside the emitters' E.
void add_outside_light(const Scene& scene, const TransportSettings& settings, SceneTransport& out,
                       Progress* progress) {
    if (!has_outside_light(scene)) return;
    update_outside_light(*out.transport, *out.patches, scene, settings.form_factors.seed, progress);
}

}  // namespace

SceneTransport build_scene_transport(const Scene& scene, const PatchMesh& base,
                                     const TransportSettings& settings, Progress* progress) {
    SceneTransport out = build_transport(scene, base, settings, progress);
    add_outside_light(scene, settings, out, progress);
    return out;
}

}  // namespace rad
