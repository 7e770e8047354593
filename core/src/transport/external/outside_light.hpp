#pragma once

// The light that reaches each patch from outside the scene: the sky through the directions that leave it,
// and the sun where its shadow rays are clear. It enters the radiosity equation as a source, ρ H_out, beside
// the emission (B = E + ρ (H + H_out)), so every transport and solver takes it as they take emitters.

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// The sky is sampled per patch on side x side strata of cosine-weighted directions, one ray each from a
// uniform point of the patch; strata at the sky's edge (where a window's frame or a roof's eave cuts it) are
// traced again as 4 x 4 sub-strata, at most kMaxSplitStrataPerSide x side of them. The sun gets side x side
// shadow rays from stratified points. side is 32 up to kOutsideLightRayBudget / 1024 patches and shrinks
// (to 4 at the least) above, so the first rays stay within the budget.
inline constexpr double kOutsideLightRayBudget = 1 << 25;
inline constexpr std::size_t kMaxSplitStrataPerSide = 3;
int outside_light_strata_side(std::size_t patches);

// H_out per patch, the mean over the patch's front: π × the mean sky radiance over the cosine-weighted
// directions that leave the scene, plus E_sun cos θ × the share of points that see the sun. Where
// `exposed_area` is given (one per patch), the mean is over the exposed part only: points that other geometry
// covers see neither. Deterministic for a seed, whatever the threads. Reports to `progress` (one per patch)
// and throws Cancelled.
std::vector<glm::dvec3> outside_irradiance(const Scene& scene, const PatchMesh& patches, const RayScene& rays,
                                           std::uint64_t seed, std::span<const double> exposed_area = {},
                                           Progress* progress = nullptr);

// Adds ρ H_out to each base patch's emission, for the refinement of hierarchical and clustered links,
// which decides where light varies from the sources' power before anything is solved. `exposed_share` is
// per patch (empty: all exposed).
void add_outside_light(const Scene& scene, const PatchMesh& base, const RayScene& rays, std::uint64_t seed,
                       std::span<const float> exposed_share, std::span<const glm::dvec3> reflectance,
                       std::span<glm::dvec3> emission, Progress* progress);

}  // namespace rad
