#pragma once

#include "rad/transport/scene_transport.hpp"

namespace rad {

// The table's entry for hierarchical radiosity: its leaves are the elements.
SceneTransport build_hierarchical_method(const Scene& scene, const PatchMesh& base,
                                         const TransportSettings& settings, Progress* progress);

}  // namespace rad
