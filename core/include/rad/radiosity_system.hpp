#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/form_factor_matrix.hpp"
#include "rad/patches.hpp"
#include "rad/scene.hpp"

namespace rad {

// The linear system B = E + ρ F B, one equation per patch and colour channel, in the arrays the solvers
// sweep: per patch its area A, reflectance ρ and emitted radiosity E (= π Le), and the form factors F.
struct RadiositySystem {
    std::vector<double> area;
    std::vector<glm::dvec3> reflectance;
    std::vector<glm::dvec3> emission;
    FormFactorMatrix form_factors;

    std::size_t size() const { return area.size(); }
};

// Gathers each patch's ρ and E from its surface's material and takes the form factors over. A patch's area
// is its exposed part (FormFactorMatrix::exposed), so B is the radiosity of what can be seen of it.
RadiositySystem make_radiosity_system(const Scene& scene, const PatchMesh& patches,
                                      FormFactorMatrix form_factors);

// The radiosity averaged over each whole patch, its covered part dark: solution × exposed area / area. This
// is what sampling points over the patch measures (a path tracer's patch estimate).
std::vector<glm::dvec3> whole_patch_radiosity(const RadiositySystem& system, const PatchMesh& patches,
                                              std::span<const glm::dvec3> radiosity);

// Throws std::invalid_argument when the arrays disagree in size, a column is out of range, or a value is
// NaN, infinite or negative (or an area is zero): the solvers rely on finite, non-negative input. Values
// that make the system unsolvable (ρ ≥ 1, rows summing over 1) pass here; the solvers report them.
void validate_radiosity_system(const RadiositySystem& system);

// Power (radiosity × area) per channel. `escaped` is the light leaving patches that reaches no patch:
// Σ A_i B_i (1 − Σ_j F_ij). `absorbed` is Σ A_i (1 − ρ_i) H_i with H = F B the light arriving per unit area.
// At convergence emitted = absorbed + escaped, to within the form factors' reciprocity error (the derivation
// uses A_i F_ij = A_j F_ji); in a closed scene nothing escapes.
struct EnergyBalance {
    glm::dvec3 emitted{0.0};
    glm::dvec3 absorbed{0.0};
    glm::dvec3 escaped{0.0};

    glm::dvec3 imbalance() const { return emitted - absorbed - escaped; }
};

EnergyBalance energy_balance(const RadiositySystem& system, std::span<const glm::dvec3> radiosity);

}  // namespace rad
