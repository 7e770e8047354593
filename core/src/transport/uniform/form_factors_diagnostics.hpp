#pragma once

#include "rad/mesh/patch_mesh.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// Row sums and reciprocity errors of a matrix whose rows are sorted by column. The reciprocity error of a
// pair is |A_i F_ij - A_j F_ji| / max(A_i F_ij, A_j F_ji), 1 when only one of the two is stored; the mean
// weighs each unordered pair by the energy it exchanges (A_i F_ij + A_j F_ji).
FormFactorDiagnostics diagnose(const FormFactorMatrix& matrix, const PatchMesh& patches);

// Replaces A_i F_ij and A_j F_ji by their mean, storing both entries wherever either was stored.
FormFactorMatrix enforce_reciprocity(const FormFactorMatrix& matrix, const PatchMesh& patches);

// Scales each row with a positive sum to sum to exactly 1 (closed scenes only: elsewhere rows sum below 1).
void normalize_rows(FormFactorMatrix& matrix);

}  // namespace rad
