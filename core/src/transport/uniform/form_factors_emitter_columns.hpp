#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "sampling/emitter_patches.hpp"
#include "sampling/patch_shapes.hpp"
#include "transport/uniform/form_factors_rows.hpp"

namespace rad {

// Light sources are small and bright. Of a patch's hemisphere rays only the few that happen to meet an
// emitter estimate its direct light, and that noise, times the emitters' radiosity, is most of what is wrong
// in a picture: each patch gets its own error, which shows as blotches (the Cornell box floor's factor to
// the light is 0.6 %, so of 4096 rays a floor patch sends about 25 meet the light: 20 % noise). So the
// hemisphere estimator leaves the emitters' columns to shadow rays aimed at the emitters:
//
// each row has T = min(hemisphere rays, kEmitterShadowRays per emitter patch) shadow rays for the emitters,
// in K = T / kRaysPerDraw draws of kRaysPerDraw rays. An emitter's weight w_j is its emitted luminance times
// a cheap, conservative estimate of the factor (from the centroids' distance, cosines and the patches'
// extent). When no more emitters can send light than there are draws, each is drawn about K p_j times (at
// least once), p_j = w_j / Σ w, and its entry is U_ij times the share of its stratified shadow rays that
// nothing blocks, U_ij the exact unoccluded factor (point-to-polygon, integrated): as before for a few
// emitters. When there are more, the K draws are a systematic sample of the weights, and an emitter drawn
// with probability K p_j < 1 has its entry divided by that probability. Every entry is an unbiased estimate,
// and the direct light Σ_j F_ij E_j, whose terms the weights follow, has little variance however many emitter
// patches there are.
inline constexpr int kEmitterShadowRays = 64;
inline constexpr int kRaysPerDraw = 16;

// One flag per patch: 1 for the listed columns.
std::vector<std::uint8_t> column_flags(std::size_t patch_count, std::span<const std::uint32_t> columns);

// The emitters' columns of every row, as above. `luminance` is each emitter patch's emitted luminance (its
// sampling weight's first factor), in the order of `emitters`; `hemisphere_rays` the rows' ray count.
RowFunction emitter_rows(const PatchMesh& patches, const RayScene& scene, std::vector<std::uint32_t> emitters,
                         std::vector<double> luminance, int hemisphere_rays, std::uint64_t seed);

// The same between receivers and emitters given apart (the leaves of a hierarchy, and the base patches that
// emit): row i is receivers[i]'s, and emitter k fills column columns[k] (ascending). A receiver lying in an
// emitter (own_column[i], where given; else the emitter whose column is i) takes none of its light.
struct EmitterSet {
    std::vector<PatchShape> shapes;
    std::vector<std::uint32_t> columns;
    std::vector<double> luminance;
};
RowFunction emitter_rows(std::vector<PatchShape> receivers, std::vector<std::uint32_t> own_column,
                         EmitterSet emitters, const RayScene& scene, double offset, int hemisphere_rays,
                         std::uint64_t seed);

// Row i of `first` and of `second`, which fill distinct columns, merged in column order.
RowFunction merged_rows(RowFunction first, RowFunction second);

}  // namespace rad
