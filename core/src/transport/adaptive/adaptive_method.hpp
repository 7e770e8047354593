#pragma once

#include "rad/transport/scene_transport.hpp"

namespace rad {

// The table's entry for adaptive subdivision: uniform form factors over patches split in passes.
SceneTransport build_adaptive_method(const Scene& scene, const PatchMesh& base,
                                     const TransportSettings& settings, Progress* progress);

}  // namespace rad
