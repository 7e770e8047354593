#include "transport/adaptive/adaptive_method.hpp"

#include <string>

#include "rad/transport/adaptive/adaptive_subdivision.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {

namespace {

std::string pass_sizes(const AdaptiveReport& report) {
    std::string sizes;
    for (const AdaptivePass& p : report.passes)
        sizes += (sizes.empty() ? "" : " -> ") + std::to_string(p.patches);
    return sizes;
}

// Its default tolerance, 0.15, is where it matched or beat uniform meshes of as many patches in both absolute
// and relative error on the Cornell box (tests/transport/test_adaptive_subdivision.cpp,
// RAD_ADAPTIVE_MEASURE=1).
AdaptiveOptions adaptive_options(const TransportSettings& settings) {
    AdaptiveOptions options;
    options.tolerance = settings.refine_tolerance > 0.0 ? settings.refine_tolerance : 0.15;
    options.min_patch_size = settings.min_patch_size;
    if (settings.max_passes > 0) options.max_passes = settings.max_passes;
    options.seed = settings.form_factors.seed;
    return options;
}

}  // namespace

SceneTransport build_adaptive_method(const Scene& scene, const PatchMesh& base,
                                     const TransportSettings& settings, Progress* progress) {
    AdaptiveResult result = subdivide_adaptively(scene, base, settings.form_factors, settings.pass_method,
                                                 settings.pass_solver, adaptive_options(settings), progress);
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

}  // namespace rad
