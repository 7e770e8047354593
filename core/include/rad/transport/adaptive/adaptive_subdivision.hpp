#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string_view>
#include <vector>

#include "rad/mesh/element_tree.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"
#include "rad/util/progress.hpp"

namespace rad {

struct AdaptiveOptions {
    // A leaf is split only while its longest edge is at least twice this, so no split makes an element whose
    // longest edge is below it (quarters have at most half their parent's longest edge, and exactly half for
    // the quarters holding it). 0: each base patch's own longest edge / 8, that is at most 3 levels.
    double min_patch_size = 0.0;
    // A leaf splits when its luminance differs from a neighbour's on the same surface by more than this share
    // of the larger of the two (in the dark, of a floor: 5 % of the scene's area-weighted mean), and by more
    // than three standard deviations of the hemisphere form factors' noise, which no split removes.
    double tolerance = 0.25;
    // Form-factor passes and solves in all, the first on the base mesh; leaves chosen after the last are not
    // split, as nothing would solve them. 1 solves the base mesh only.
    int max_passes = 4;
    std::uint64_t seed = 1;  // for the shadow rays
};

// Why the loop ended. memory_budget: the chosen splits did not all fit the form factors' memory budget
// (FormFactorOptions::max_memory_bytes); the most important were made and solved.
enum class AdaptiveStop { nothing_to_split, max_passes, memory_budget };
std::string_view adaptive_stop_name(AdaptiveStop stop);  // "nothing to split", "max passes", "memory budget"

// The most leaves whose form-factor pass fits the budget of `ff` (form_factor_memory_estimate); the leaves
// never exceed it, and a base mesh above it is refused with MemoryBudgetError before any work.
std::size_t adaptive_leaves_that_fit(const FormFactorOptions& ff);

// One form-factor pass and solve, and the splits chosen from its solution.
struct AdaptivePass {
    std::size_t patches = 0;  // leaves solved
    double form_factor_seconds = 0.0;
    double solve_seconds = 0.0;
    double criteria_seconds = 0.0;  // choosing the splits (0 after the last pass)
    std::size_t solver_steps = 0;
    SolverStatus solver_status = SolverStatus::running;
    // Leaves each criterion asked to split, counted under both when both did, before the size limit and
    // the memory budget.
    std::size_t gradient_leaves = 0;
    std::size_t shadow_leaves = 0;
    std::size_t too_small = 0;  // asked, but at the minimum size
    std::size_t split = 0;      // leaves split after this pass (each adds three)
};

struct AdaptiveReport {
    std::vector<AdaptivePass> passes;
    AdaptiveStop stop = AdaptiveStop::nothing_to_split;
    std::size_t shadow_sources = 0;  // in the last pass that chose splits
    double seconds = 0.0;
};

// The last pass's leaves, its system (the caller may step a fresh solver on it) and its solution.
struct AdaptiveResult {
    ElementTree tree;
    std::vector<std::uint32_t> leaves;  // patch k of `patches` is element leaves[k] of `tree`
    PatchMesh patches;
    UniformTransport system;
    std::vector<glm::dvec3> radiosity;
    AdaptiveReport report;
};

// Solves the scene on `base`, then splits the leaves where radiosity changes steeply between neighbours on a
// surface (gradient) or where the share of a bright patch's light that reaches a leaf changes across it
// (shadow boundaries: the emitters and brightest patches, traced with shadow rays), and solves again, until
// nothing is left to split or a bound is reached. The result depends on the seeds only, not on threads.
// Throws InputError for bad options, MemoryBudgetError when the base mesh's form factors alone exceed the
// budget (with a coarser patch size, as compute_form_factors), what compute_form_factors and make_solver
// throw, and Cancelled when `progress` is cancelled.
AdaptiveResult subdivide_adaptively(const Scene& scene, const PatchMesh& base, const FormFactorOptions& ff,
                                    SolverMethod method, const SolverOptions& solver,
                                    const AdaptiveOptions& options, Progress* progress = nullptr);

}  // namespace rad
