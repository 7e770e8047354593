#pragma once

// The leaves' reach, measured by rays, and the scales that make the links conserve energy. Private to the
// library.

#include "rad/ray/ray_scene.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"
#include "transport/leaf_balance.hpp"

namespace rad {

// Rays per leaf that measure its form factor to the whole scene.
inline constexpr std::size_t kReachRays = 64;

// h.reach: per leaf, the share of cosine-weighted rays that meet the front of a surface; h.exposed, the
// share that is not covered. A surface lying on another face to face (a box's bottom on a floor) is covered
// there: rays that meet the other within `contact`, head on, are covered, and do not reach.
void measure_reach(ClusterHierarchy& h, const RayScene& rays, double offset, double contact,
                   std::uint64_t seed);

// A leaf's area less its covered part: what emits, absorbs and reflects into the scene.
double exposed_area(const ClusterHierarchy& h, std::size_t leaf);

// h.receive_scale and h.send_scale, so that the leaves' gather T' = diag(receive) T diag(send) has, for
// every leaf, the row sum (what it gathers of a uniform radiosity) and the column share (what arrives
// somewhere of its own light, per unit of exposed area) both equal to the reach of its exposed part: light
// then leaves each leaf in the amount it arrives, and emitted = absorbed + escaped holds. The target is the
// links' own row sum moved towards the measured reach by what exceeds twice the measurement's standard error,
// so a closed scene's leaves (no ray escapes, no noise) gather exactly 1. Both scales are at most
// kMaxLeafScale. Returns the largest row error left among the leaves whose scale is not at that bound.
double balance_leaves(ClusterHierarchy& h);

}  // namespace rad
