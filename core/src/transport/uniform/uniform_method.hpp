#pragma once

#include "rad/transport/scene_transport.hpp"

namespace rad {

// The table's entry for uniform patches: form factors between every pair of base patches.
SceneTransport build_uniform_method(const Scene& scene, const PatchMesh& base,
                                    const TransportSettings& settings, Progress* progress);

}  // namespace rad
