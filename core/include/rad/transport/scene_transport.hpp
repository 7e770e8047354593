#pragma once

#include <memory>
#include <string_view>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/adaptive/adaptive_subdivision.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"
#include "rad/transport/hierarchical/hierarchical_radiosity.hpp"
#include "rad/transport/transport.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// How light transport over a scene is built:
//   uniform       one patch size everywhere, a form factor for every pair that sees each other;
//   adaptive      coarser uniform patches first, then split where the radiosity changes steeply between
//                 neighbours or a shadow edge crosses, form factors and solve repeated; ends in uniform form
//                 factors over the last leaves;
//   hierarchical  coarse base patches split into a quadtree as links between elements need it (Hanrahan,
//                 Salzman and Aupperle 1991);
//   clustered     hierarchical radiosity with volume clusters over the base patches above their quadtrees,
//                 refined from the root cluster's link to itself (Smits, Arvo and Greenberg 1994);
//   automatic     uniform patches for a scene of few patches, clustering beyond (choose_subdivision).
enum class Subdivision { automatic, uniform, adaptive, hierarchical, clustered };

// "auto", "uniform", "adaptive", "hierarchical", "clustered".
std::string_view subdivision_name(Subdivision subdivision);
const std::vector<Subdivision>& all_subdivisions();  // automatic first

// Uniform patches up to this many at their default size, clustering beyond: below it uniform patches
// reach a given error sooner, above it clustering does (docs/measurements.md, "Scaling").
inline constexpr std::size_t kAutomaticUniformPatches = 10'000;

// What `automatic` means for a scene whose uniform mesh has `uniform_patches` patches; any other
// subdivision is itself.
Subdivision choose_subdivision(Subdivision requested, std::size_t uniform_patches);

// Whether that subdivision's transport has a form-factor matrix (see check_solver_supported); automatic
// must be chosen first (false).
bool has_matrix(Subdivision subdivision);

struct TransportSettings {
    Subdivision subdivision = Subdivision::automatic;
    FormFactorOptions form_factors;                   // uniform and adaptive
    AdaptiveOptions adaptive;                         // adaptive
    HierarchicalOptions hierarchical;                 // hierarchical
    ClusteredOptions clustered;                       // clustered
    SolverMethod pass_method = SolverMethod::jacobi;  // adaptive: how each pass is solved
    SolverOptions pass_solver;
};

// A transport built over a meshed scene, and its elements as patches (in the transport's order): the base
// mesh's own for uniform transport, the leaves otherwise.
struct SceneTransport {
    std::unique_ptr<Transport> transport;
    const PatchMesh* patches = nullptr;  // the base, or refined_patches, or the hierarchy's leaves
    std::unique_ptr<const PatchMesh> refined_patches;
};

// The one place that knows the kinds of transport. `base` must outlive the result; for `automatic` it is
// taken as the uniform mesh (choose_subdivision of its size). Throws what the builders
// throw (InputError for bad settings or a pass over the memory budget) and Cancelled when `progress` is
// cancelled.
SceneTransport build_scene_transport(const Scene& scene, const PatchMesh& base,
                                     const TransportSettings& settings, Progress* progress = nullptr);

}  // namespace rad
