#pragma once

#include <memory>
#include <string_view>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/transport.hpp"
#include "rad/transport/transport_methods.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/util/progress.hpp"

namespace rad {

struct TransportSettings {
    Subdivision subdivision = Subdivision::automatic;
    // Every method's rays (0: each method's default: hemisphere rays per patch, shadow rays per pair or per
    // link) and seed; its memory budget (--max-memory) bounds every method's interactions.
    FormFactorOptions form_factors;
    // How finely a refining method refines (--refine-tol) and its smallest element (--min-patch-size); 0
    // takes the method's default.
    double refine_tolerance = 0.0;
    double min_patch_size = 0.0;
    int max_passes = 0;  // a method that refines in passes (adaptive): at most this many; 0: its default
    SolverMethod pass_method = SolverMethod::jacobi;  // adaptive: how each pass is solved
    SolverOptions pass_solver;
};

// A transport built over a meshed scene, and its elements as patches (in the transport's order): the base
// mesh's own for uniform transport, the leaves otherwise.
struct SceneTransport {
    const TransportMethod* method = nullptr;  // the table's entry that built it
    std::unique_ptr<Transport> transport;
    const PatchMesh* patches = nullptr;  // the base, or refined_patches, or the hierarchy's leaves
    std::unique_ptr<const PatchMesh> refined_patches;
    // A ray scene over the elements where building traced them (the sky's and sun's light), for whoever
    // traces them next (the display, an edit of the sky); null otherwise.
    std::shared_ptr<const RayScene> element_rays;
};

// The transport of the settings' method (its table entry's build), with the sky's and sun's light on its
// elements. `base` must outlive the result; for `automatic` it is taken as the uniform mesh
// (choose_subdivision of its size). Throws what the builders
// throw (InputError for bad settings or a pass over the memory budget) and Cancelled when `progress` is
// cancelled.
SceneTransport build_scene_transport(const Scene& scene, const PatchMesh& base,
                                     const TransportSettings& settings, Progress* progress = nullptr);

}  // namespace rad
