#pragma once

#include <span>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"

namespace rad {

// Turns the rows of whole patches into rows of their exposed parts: with f_i = 1 − covered[i], row i
// becomes F_ij / f_i and matrix.exposed[i] = f_i. A patch a box half covers otherwise reflects half its
// light into the box, where it is lost: in a closed room at ρ = 0.95 that lost 10 % of all light.
void expose_rows(FormFactorMatrix& matrix, std::span<const double> covered);

// Σ A_i covered_i / Σ A_i (0 when `covered` is empty).
double covered_area_fraction(const PatchMesh& patches, std::span<const double> covered);

}  // namespace rad
