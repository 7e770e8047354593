#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "rad/form_factors.hpp"
#include "rad/progress.hpp"
#include "rad/radiosity_system.hpp"
#include "rad/solver.hpp"
#include "rad/vertex_colours.hpp"
#include "scene_options.hpp"
#include "solver_options.hpp"
#include "subdivision_options.hpp"

namespace rad {

// The options of every command that solves a scene (solve, render, view, bench), registered together.
struct PipelineOptions {
    SceneOptions scene;
    FormFactorOptions form_factors;
    SolverCommandOptions solver;
    SubdivisionOptions subdivision;
    DisplayOptions display;
};

void add_pipeline_options(CLI::App& command, PipelineOptions& options);

// How much work was done, so callers and tests can check that nothing runs twice.
struct WorkCounts {
    std::size_t form_factor_passes = 0;
    std::size_t solver_steps = 0;
};

struct StageSeconds {
    double mesh = 0.0;
    double form_factors = 0.0;
    double solve = 0.0;
};

// From a meshed scene to radiance per display vertex: form factors once, then the solver stepped by the
// caller (or to the end), and the display mesh built once. The viewer steps it; the commands run it through.
class RadiosityPipeline {
  public:
    // Loads and meshes the scene (for hierarchical radiosity, into base patches). Throws InputError for bad
    // input or options.
    explicit RadiosityPipeline(const PipelineOptions& options);

    // Runs the form-factor pass (adaptive: the passes; hierarchical: builds the links) and makes the solver;
    // does nothing the second time. Adaptive and hierarchical subdivision change patches() and display().
    void prepare(Progress* progress = nullptr);
    // One solver step (prepares first if needed).
    StepReport step();
    // Steps until the solver finishes (converged, limit, or cannot converge).
    const StepReport& solve(Progress* progress = nullptr);
    // A fresh solver from B = E with this method and these options, keeping the form factors (prepares
    // first if needed): the viewer's "reset to emission only" and its solver switch.
    void restart_solver(SolverMethod method, const SolverOptions& options);

    const LoadedScene& loaded() const { return loaded_; }
    // The patches the solution belongs to: the meshed scene's, or after prepare the adaptive or
    // hierarchical leaves.
    const PatchMesh& patches() const { return patches_ ? *patches_ : loaded_.patches; }
    Subdivision subdivision() const { return subdivision_; }
    // Hierarchical radiosity's figures (zero otherwise).
    const HierarchicalReport& hierarchical_report() const { return hierarchical_report_; }
    // Adaptive subdivision's passes (empty otherwise).
    const AdaptiveReport& adaptive_report() const { return adaptive_report_; }
    // Built on first use, so `solve` never pays for it.
    const DisplayMesh& display() const;
    const RadiositySystem& system() const { return *system_; }
    const Solver& solver() const { return *solver_; }
    const FormFactorReport& form_factor_report() const { return form_factor_report_; }
    const SolverOptions& solver_options() const { return solver_options_; }
    SolverMethod method() const { return method_; }

    // Emitted, absorbed and escaped power of the solution as it stands (after prepare).
    EnergyBalance energy_balance() const;

    // Linear radiance L = B / π per display vertex for the solution as it stands (black before prepare).
    std::vector<glm::vec3> vertex_radiance() const;

    const WorkCounts& work() const { return work_; }
    const StageSeconds& seconds() const { return seconds_; }

  private:
    void prepare_uniform(Progress* progress);
    void prepare_hierarchical(Progress* progress);
    void prepare_adaptive(Progress* progress);
    void use_patches(const PatchMesh& patches);

    PipelineOptions options_;
    Subdivision subdivision_ = Subdivision::uniform;
    LoadedScene loaded_;
    const PatchMesh* patches_ = nullptr;  // the leaves, when they are not loaded_.patches
    std::unique_ptr<HierarchicalSystem> hierarchy_;
    std::optional<PatchMesh> adaptive_patches_;
    HierarchicalReport hierarchical_report_;
    AdaptiveReport adaptive_report_;
    mutable std::optional<DisplayMesh> display_;  // of patches(), once asked for
    SolverMethod method_;
    SolverOptions solver_options_;
    std::optional<RadiositySystem> system_;
    std::unique_ptr<Solver> solver_;
    FormFactorReport form_factor_report_;
    WorkCounts work_;
    StageSeconds seconds_;
};

}  // namespace rad
