#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "transport/uniform/form_factors_rows.hpp"

namespace rad {

// Light sources are small and bright. Of a patch's hemisphere rays only the few that happen to meet an
// emitter estimate its direct light, and that noise, times the emitters' radiosity, is most of what is wrong
// in a picture: each patch gets its own error, which shows as blotches (the Cornell box floor's factor to
// the light is 0.6 %, so of 4096 rays a floor patch sends about 25 meet the light: 20 % noise). So the
// hemisphere estimator leaves the emitters' columns to the analytic one: point-to-polygon factors times the
// visible share of kEmitterShadowRays shadow rays, whose error is only where the light is partly hidden, and
// there it is a stratified estimate. The shadow rays of one row cost at most as many rays as its hemisphere
// rays: kEmitterShadowRays per emitter patch, fewer when there are many, down to kMinEmitterShadowRays; below
// that the emitters are left to the hemisphere rays (large emitters are hit by many of them, so little is
// lost).
inline constexpr int kEmitterShadowRays = 64;
inline constexpr int kMinEmitterShadowRays = 16;

// Shadow rays per (patch, emitter patch) pair, or 0 when the emitters' columns stay with the hemisphere.
int emitter_shadow_rays(std::size_t emitter_patches, int hemisphere_rays);

// The patches of the emitting surfaces, sorted: the columns to estimate analytically when
// emitter_shadow_rays allows.
std::vector<std::uint32_t> emitting_patches(const PatchMesh& patches,
                                            std::span<const std::uint32_t> emitting_surfaces);

// One flag per patch: 1 for the listed columns.
std::vector<std::uint8_t> column_flags(std::size_t patch_count, std::span<const std::uint32_t> columns);

// Row i of `first` and of `second`, which fill distinct columns, merged in column order.
RowFunction merged_rows(RowFunction first, RowFunction second);

}  // namespace rad
