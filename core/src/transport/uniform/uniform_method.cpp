#include "transport/uniform/uniform_method.hpp"

#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {

SceneTransport build_uniform_method(const Scene& scene, const PatchMesh& base,
                                    const TransportSettings& settings, Progress* progress) {
    FormFactorReport report;
    FormFactorMatrix form_factors = compute_form_factors(base, settings.form_factors, &report, progress);
    SceneTransport out;
    out.transport = std::make_unique<UniformTransport>(
        make_uniform_transport(scene, base, std::move(form_factors), report));
    out.patches = &base;
    return out;
}

}  // namespace rad
