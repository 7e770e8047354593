#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/util/progress.hpp"
#include "transport/adaptive/adaptive_leaves.hpp"

namespace rad {

// Shadow sources are base patches, brightest first by power (luminance × exposed area, summed over their
// leaves), taken until they carry kSourcePowerShare of the scene's power, at most kMaxShadowSources: the
// emitters and the patches lit most, whose shadows matter.
inline constexpr double kSourcePowerShare = 0.75;
inline constexpr std::size_t kMaxShadowSources = 32;

// A leaf asks to be split for a source when the share of the source's light that reaches its points (from
// sample points on the source, weighted by the point-to-point kernel) changes by at least kVisibilityChange
// across the leaf, and the source, seen unoccluded, would bring at least kShadowShare of its irradiance.
inline constexpr double kVisibilityChange = 0.25;
inline constexpr double kShadowShare = 0.1;
// Stratified points on a source, the same for all of a leaf's points, so their differences are not noise.
inline constexpr int kSourceSamples = 16;
// The leaf's corners are pulled this share of the way to its centroid, so a corner on the edge of what
// covers it (a floor corner under a box's side) is clearly on one side.
inline constexpr double kCornerPull = 0.02;

struct ShadowSource {
    std::uint32_t base_patch = 0;
    double luminance = 0.0;  // its mean radiosity's
};

std::vector<ShadowSource> shadow_sources(const SolvedLeaves& leaves);

// Where the rays go: a RayScene over the base mesh (the leaves' geometry) and the offset that lifts ray ends
// off surfaces.
struct ShadowRays {
    const PatchMesh& base;
    const RayScene& scene;
    double offset = 0.0;
    std::uint64_t seed = 1;
};

// Per leaf, the largest over sources of min(visibility change / kVisibilityChange, unoccluded share /
// kShadowShare); a leaf asks to be split when it is at least 1. Depends on the seed only, not on threads.
// Advances `progress` once per leaf and stops early (the result then meaningless) when it is cancelled.
std::vector<double> shadow_excess(const SolvedLeaves& leaves, std::span<const ShadowSource> sources,
                                  const ShadowRays& rays, Progress* progress);

}  // namespace rad
