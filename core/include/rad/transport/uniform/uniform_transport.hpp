#pragma once

#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/transport/transport.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// Light transport by a form factor for every pair of patches that see each other: gather is F·B, one pass
// over the sparse rows. Uniform patches and the last pass of adaptive subdivision end here.
class UniformTransport final : public Transport {
  public:
    void gather(std::span<const glm::dvec3> radiosity, std::span<glm::dvec3> irradiance) const override;
    std::vector<double> reach() const override;   // the row sums
    std::vector<double> escape() const override;  // the rows' escaped rays, where measured
    const FormFactorMatrix* matrix() const override { return &form_factors; }
    TransportReport report() const override;

    FormFactorMatrix form_factors;
    // How the form factors were made (empty for a hand-made transport).
    FormFactorReport form_factor_report;
    // "uniform", or "adaptive" with the passes' figures in `details` and `notes`.
    std::string kind = "uniform";
    std::size_t form_factor_passes = 1;
    std::vector<TransportDetail> details;
    std::string notes;
};

// Gathers each patch's ρ and E from its surface's material and takes the form factors over. A patch's area
// is its exposed part (FormFactorMatrix::exposed), so B is the radiosity of what can be seen of it.
UniformTransport make_uniform_transport(const Scene& scene, const PatchMesh& patches,
                                        FormFactorMatrix form_factors, const FormFactorReport& report = {});

// The radiosity averaged over each whole patch, its covered part dark: solution × exposed area / area. This
// is what sampling points over the patch measures (a path tracer's patch estimate).
std::vector<glm::dvec3> whole_patch_radiosity(const Transport& transport, const PatchMesh& patches,
                                              std::span<const glm::dvec3> radiosity);

// Throws std::invalid_argument when the matrix does not have `rows` rows, a column is out of range, or a
// form factor is NaN, infinite or negative.
void validate_form_factor_matrix(const FormFactorMatrix& form_factors, std::size_t rows);

// validate_elements and validate_form_factor_matrix.
void validate_uniform_transport(const UniformTransport& transport);

}  // namespace rad
