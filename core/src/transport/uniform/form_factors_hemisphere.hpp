#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "ray/ray_offset.hpp"
#include "sampling/hemisphere_rays.hpp"
#include "transport/uniform/form_factors_rows.hpp"

namespace rad {

// F_ij = (1/N) Σ_k weight_k [ray k first meets the front of patch j]. Rays that meet a back face first are
// blocked and count for no patch; rays that meet nothing have escaped.
// covered[i] receives the share of patch i that other geometry covers (covered_share), measured for the
// patches whose rays met back faces, and escaped[i] the weighted share of its rays that met nothing. Both
// must have one element per patch.
// Rays that meet a patch marked in `skipped` (one flag per patch, or empty) count for nothing: another
// estimator fills those columns (emitter_columns).
RowFunction hemisphere_rows(const PatchMesh& patches, const RayScene& scene, int rays, std::uint64_t seed,
                            std::vector<double>& covered, std::vector<double>& escaped,
                            std::vector<std::uint8_t> skipped = {});

}  // namespace rad
