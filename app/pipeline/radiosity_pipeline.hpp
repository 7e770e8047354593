#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "pipeline/scene_options.hpp"
#include "pipeline/solver_options.hpp"
#include "pipeline/subdivision_options.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/scene_transport.hpp"
#include "rad/util/progress.hpp"

namespace rad {

// The options of every command that solves a scene (solve, render, view, bench), registered together.
struct PipelineOptions {
    SceneOptions scene;
    FormFactorOptions form_factors;
    SolverCommandOptions solver;
    SubdivisionOptions subdivision;
    DisplayOptions display;
};

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

// From a meshed scene to radiance per display vertex: the transport built once, then the solver stepped by
// the caller (or to the end), and the display mesh built once. The viewer steps it; the commands run it
// through. It never asks which kind of transport it holds.
// The options a saved solution was solved with, over `base` (what the file does not hold: the memory
// budget, the display, the threads).
PipelineOptions options_from_saved(const SavedSettings& settings, const PipelineOptions& base);

class RadiosityPipeline {
  public:
    // Loads and meshes the scene (for hierarchical radiosity, into base patches). Throws InputError for bad
    // input or options.
    explicit RadiosityPipeline(const PipelineOptions& options);
    // From a saved solution (read from `path`, named in errors): patches(), display() and vertex_radiance()
    // show the saved state at once, with no transport. prepare() rebuilds the transport from the saved scene
    // and settings (it is not saved) and the solver continues from the saved radiosity (southwell's by
    // jacobi, as southwell cannot start from a given radiosity). Throws InputError naming the file when the
    // settings cannot be used.
    RadiosityPipeline(SavedSolution saved, const std::string& path, const DisplayOptions& display = {});

    // Builds the transport (form factors, adaptive passes or hierarchical links) and makes the solver; does
    // nothing the second time. Adaptive and hierarchical subdivision change patches() and display().
    void prepare(Progress* progress = nullptr);
    // One solver step (prepares first if needed).
    StepReport step();
    // Steps until the solver finishes (converged, limit, or cannot converge).
    const StepReport& solve(Progress* progress = nullptr);
    // A fresh solver from B = E with this method and these options, keeping the transport (prepares first
    // if needed): the viewer's "reset to emission only" and its solver switch. Throws InputError naming
    // --solver for a method the transport cannot run.
    void restart_solver(SolverMethod method, const SolverOptions& options);

    // The viewer's edit: the material named `name` takes this reflectance (kept as it is on a textured
    // material, whose texels give it) and emitted radiance Le on every surface that has it. The transport
    // keeps its form factors or links; the solver starts again from the solution as it stands (southwell's
    // by jacobi, which can start from any radiosity). After prepare. Throws InputError naming the material
    // for a reflectance outside [0, 1), a negative or non-finite emission, or a name no surface has.
    void edit_material(const std::string& name, const glm::dvec3& reflectance,
                       const glm::dvec3& emitted_radiance);

    // The viewer's edit of the light from outside: `sky` and `sun` as --sky and --sun take them (empty: as
    // the scene was opened). The sky's and sun's light on each element is measured again (rays, not form
    // factors); the solver starts again from the solution as it stands. After prepare. Throws InputError
    // naming --sky or --sun for a bad value, and Cancelled when `progress` is cancelled (nothing changes
    // then).
    void edit_outside_light(const std::string& sky, const std::string& sun, Progress* progress = nullptr);

    const LoadedScene& loaded() const { return loaded_; }
    // The patches the solution belongs to: the meshed scene's, or after prepare the adaptive or
    // hierarchical leaves.
    const PatchMesh& patches() const {
        if (built_.patches) return *built_.patches;
        return saved_ ? saved_->patches : loaded_.patches;
    }
    Subdivision subdivision() const { return subdivision_; }
    // Built on first use, so `solve` never pays for it.
    const DisplayMesh& display() const;
    // A display of the solution with these options (build_solution_display): a hierarchy's leaves drawn on
    // patches of the uniform size (display_patch_size) in smooth mode. Before prepare (a preview while the
    // transport is built), a display of patches() with the emitters' direct light at its vertices
    // (add_preview_direct_light).
    DisplayMesh build_display(const DisplayOptions& options, Progress* progress = nullptr) const;
    // Builds display() now, reporting the final gather's progress (a render's stage that can take seconds).
    void prepare_display(Progress* progress) const;
    // Adds the emitters' direct light to the vertices of a display mesh of patches() before prepare: no
    // patch holds any of it yet, so each vertex keeps its own value, to be shown with direct_share 1 over
    // preview_radiosity().
    void add_preview_direct_light(DisplayMesh& display) const;
    // E per patch of patches(): the radiosity before any light is reflected.
    std::vector<glm::dvec3> preview_radiosity() const;
    // What a display mesh of patches() needs for texel detail: the scene and each patch's reflectance (the
    // transport's after prepare, the saved one, or else the patches' mean albedo, which uniform transport
    // will use).
    DisplayTexturing display_texturing() const;
    // After prepare.
    const Transport& transport() const { return *built_.transport; }
    const Solver& solver() const { return *solver_; }
    const SolverOptions& solver_options() const { return solver_options_; }
    SolverMethod method() const { return method_; }

    // Emitted, absorbed and escaped power of the solution as it stands (after prepare).
    EnergyBalance energy_balance() const;

    // Linear radiance L = B / π per display vertex for the solution as it stands (black before prepare).
    std::vector<glm::vec3> vertex_radiance() const;

    // The saved solution the pipeline was made from, until prepare() replaces it by a transport; else null.
    const SavedSolution* saved() const { return saved_ && !solver_ ? &*saved_ : nullptr; }
    // The state to save (after prepare): the scene, the settings, the elements and the solution.
    SavedSolution saved_solution() const;

    const WorkCounts& work() const { return work_; }
    const StageSeconds& seconds() const { return seconds_; }

  private:
    TransportSettings transport_settings() const;
    // The size of the patches a solution is drawn on in smooth mode, 0 for its own (DisplayPatches): the
    // uniform size for a hierarchy, whose leaves hold light linked to larger elements.
    double display_patch_size() const;
    // ρ H_d per element: the emitters' light reflected once, by the transport (after prepare).
    std::vector<glm::dvec3> element_direct() const;
    void continue_saved();
    // A fresh solver of the same method and options from the solution as it stands, after an edit of the
    // transport's sources.
    void restart_from_solution();
    // --subdivision auto: uniform patches or clustering by the scene's faces, then the uniform mesh's size
    // (choose_subdivision), and the patches that subdivision is meshed with.
    void choose_automatic_subdivision();

    PipelineOptions options_;
    std::optional<SavedSolution> saved_;
    std::string saved_path_;
    Subdivision subdivision_ = Subdivision::automatic;  // the method, once the constructor has chosen it
    LoadedScene loaded_;
    Sky opened_sky_;  // the scene's sky and sun as opened, which an empty edit returns to
    Sun opened_sun_;
    SceneTransport built_;
    mutable std::optional<DisplayMesh> display_;  // of patches(), once asked for
    mutable std::vector<glm::dvec3>
        loaded_albedo_;  // of loaded_.patches, for display_texturing before prepare
    SolverMethod method_;
    SolverOptions solver_options_;
    std::unique_ptr<Solver> solver_;
    WorkCounts work_;
    StageSeconds seconds_;
};

}  // namespace rad
