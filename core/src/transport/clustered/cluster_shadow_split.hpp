#pragma once

// Splitting the leaves that a shadow's edge crosses, so that the aimed direct light draws the shadow as
// sharply as the smallest elements allow. Private to the library.

#include <cstddef>
#include <cstdint>
#include <span>

#include "rad/ray/ray_scene.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"

namespace rad {

// Splits (repeatedly, down to elements of longest edge 2 × min_patch_size) every leaf across which the
// visibility of an emitter base patch changes by enough to leave an error over `threshold` in its radiosity:
// ρ × the emitter's E × the unoccluded factor × the change in its visible share, from shadow rays between a
// few points of the leaf and of the emitter. At most `max_new_leaves` are added. Sets h.leaves; returns the
// number of splits.
std::size_t split_shadow_edges(ClusterHierarchy& h, const PatchMesh& base,
                               std::span<const std::uint32_t> emitters, const RayScene& rays, double offset,
                               double min_patch_size, double threshold, std::size_t max_new_leaves);

}  // namespace rad
