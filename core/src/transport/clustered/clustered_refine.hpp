#pragma once

// Refinement of the cluster hierarchy's links, from the root's link to itself. Private to the library.

#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"

namespace rad {

// Makes h.links (unsorted): every pair of nodes that exchange light, at the level where the error bound of
// the link is below the tolerance. Splits elements of h.tree as it goes (reflectance and emission follow).
// `estimate`, when given, is a first solution's luminance per element and per cluster (an element split
// since takes its nearest ancestor's) in place of the emission-based guess of each source's radiosity.
struct RadiosityEstimate {
    std::vector<double> element, cluster;
    double mean = 0.0;  // over the scene's area
};
void refine_cluster_links(ClusterHierarchy& h, const RayScene& rays, double ray_offset,
                          const ClusteredOptions& options, ClusteredReport& report, Progress* progress,
                          const RadiosityEstimate* estimate = nullptr);

}  // namespace rad
