#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <vector>

namespace rad {

struct FormFactorMatrix;

// A figure of one transport method beyond what every method reports (row sums, rounds, leaves...).
struct TransportDetail {
    std::string name;  // snake_case, as written in the solution JSON
    double value = 0.0;
};

// What building a transport cost and made, in the same terms for every method.
struct TransportReport {
    std::string kind;              // "uniform", "adaptive", "hierarchical"
    std::string interaction_name;  // what the interactions are: "form factors" or "links"
    std::size_t elements = 0;      // what the solution is indexed by
    std::size_t interactions = 0;  // stored form factors, or links
    std::size_t memory_bytes = 0;  // of the interactions and what gather reads besides
    std::uint64_t rays = 0;
    double seconds = 0.0;
    std::size_t form_factor_passes = 0;  // how many times the scene's interactions were computed
    std::vector<TransportDetail> details;
    std::string notes;  // one line for people (adaptive passes, limits reached), or empty
};

// Light transport between the elements the solution is indexed by (patches, or the leaves of a hierarchy):
// per element its area A (the exposed part, where other geometry covers some of it), reflectance ρ and
// emitted radiosity E (= π Le), and the one operation every solver needs, gather(B) = H, the irradiance each
// element receives per unit area from radiosity B. The radiosity equation is B = E + ρ H(B); a Jacobi step
// is exactly that. Methods that need the coefficients themselves (Gauss-Seidel, Southwell, CG, direct) read
// matrix(), which only form-factor transports have.
class Transport {
  public:
    virtual ~Transport() = default;

    std::size_t size() const { return area.size(); }

    // H_i = Σ_j F_ij B_j for the transport's F, into `irradiance` (one per element). Deterministic: the
    // same for any number of threads. Call it from one thread at a time.
    virtual void gather(std::span<const glm::dvec3> radiosity, std::span<glm::dvec3> irradiance) const = 0;
    // Per element, the share of the light it sends that reaches other elements: Σ_j F_ij, the row sum (at
    // most about 1; 1 in a closed scene). What is left escapes the scene.
    virtual std::vector<double> reach() const = 0;
    // Per element, the measured share of the light it sends that meets nothing and leaves the scene;
    // energy_balance takes at most 1 − reach of it, and the rest of 1 − reach meets the backs of one-sided
    // surfaces, which absorb it. By default (a transport that does not tell the two apart) 1: all of
    // 1 − reach escapes.
    virtual std::vector<double> escape() const;
    // The form factors as a sparse matrix, or nullptr where the transport is not one (links).
    virtual const FormFactorMatrix* matrix() const { return nullptr; }
    virtual TransportReport report() const = 0;

    std::vector<double> area;
    std::vector<glm::dvec3> reflectance;
    // What each element sends before any bounce: its emitted radiosity E, plus ρ H_out where a sky or sun
    // lights the scene (the equation is B = emission + ρ H(B)).
    std::vector<glm::dvec3> emission;
    // Per element, H_out: the irradiance from the sky and the sun (empty when neither lights the scene).
    std::vector<glm::dvec3> outside;

  protected:
    Transport() = default;
    Transport(const Transport&) = default;
    Transport(Transport&&) = default;
    Transport& operator=(const Transport&) = default;
    Transport& operator=(Transport&&) = default;
};

// Throws std::invalid_argument when the per-element arrays differ in size or hold NaN, infinity, negative
// values or zero areas: the solvers rely on finite, non-negative input. Values that make the system
// unsolvable (ρ ≥ 1, rows summing over 1) pass here; the solvers report them.
void validate_elements(const Transport& transport);

// Power (radiosity × area) per channel, for every transport alike. `emitted` is the emitters' Σ A_i E_i and
// `outside` the light the sky and sun bring in, Σ A_i H_out,i. Of the light leaving elements that reaches no
// element, Σ A_i B_i (1 − reach_i), `escaped` left the scene (Σ A_i B_i escape_i) and `behind` met the
// backs of one-sided surfaces, which absorb it. `absorbed` is Σ A_i (1 − ρ_i) (H_i + H_out,i) with
// H = gather(B), plus `behind`. At convergence emitted + outside = absorbed + escaped, to within the
// transport's reciprocity error (the derivation uses A_i F_ij = A_j F_ji); in a closed scene nothing escapes.
struct EnergyBalance {
    glm::dvec3 emitted{0.0};
    glm::dvec3 outside{0.0};
    glm::dvec3 absorbed{0.0};
    glm::dvec3 escaped{0.0};
    glm::dvec3 behind{0.0};  // of absorbed

    glm::dvec3 imbalance() const { return emitted + outside - absorbed - escaped; }
};

EnergyBalance energy_balance(const Transport& transport, std::span<const glm::dvec3> radiosity);

}  // namespace rad
