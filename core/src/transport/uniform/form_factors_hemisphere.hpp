#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "transport/uniform/form_factors_rows.hpp"

namespace rad {

// Rays start off their patch, along its normal, so that they do not hit the patch they leave: Embree works in
// float. The offset is the larger of kRayOffsetFraction of the scene's bounding-box diagonal and
// kRayOffsetUlps float steps of the scene's largest coordinate (for a scene far from the origin, where float
// steps are coarse). Surfaces that face each other closer than the offset do not see each other, so it is
// kept small: 3.8e-6 of the size of a unit cube at the origin, which plates 1e-5 apart still resolve.
inline constexpr double kRayOffsetFraction = 2e-6;
inline constexpr double kRayOffsetUlps = 32.0;

double ray_offset(const PatchMesh& patches);

// The hemisphere estimator's rays for one patch: origins stratified over the patch (bilinear map for quads,
// an area-uniform map for triangles) paired at random with stratified cosine-weighted directions. weights[k]
// is the bilinear map's Jacobian at ray k over the patch's area (1 for parallelograms and triangles), which
// makes the estimate exact in expectation for any quad. The rays depend only on (seed, patch).
void hemisphere_rays(const PatchMesh& patches, std::uint32_t patch, std::uint64_t seed, double offset,
                     std::span<Ray> rays, std::span<double> weights);

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
