#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "pipeline/scene_options.hpp"
#include "pipeline/solver_options.hpp"
#include "pipeline/subdivision_options.hpp"
#include "rad/display/display_mesh.hpp"
#include "rad/display/gather_table.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/solve/solution.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/transport.hpp"
#include "rad/transport/transport_methods.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/util/progress.hpp"

namespace rad {

class RayScene;
struct SceneTransport;
struct TransportSettings;

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

// The options a solution was solved with, over `base` (what the solution does not hold: the memory budget,
// the display, the threads).
PipelineOptions options_from_solution(const SolutionSettings& settings, const PipelineOptions& base);

// From a meshed scene to radiance per display vertex: the transport built once, then the solver stepped by
// the caller (or to the end), and the display mesh built once. The viewer steps it; the commands run it
// through. It never asks which kind of transport it holds, nor where its solution came from: a solution
// just solved and one opened from a file are the same Solution, drawn by the same display builder.
class RadiosityPipeline {
  public:
    // Loads and meshes the scene (for hierarchical radiosity, into base patches). Throws InputError for bad
    // input or options.
    explicit RadiosityPipeline(const PipelineOptions& options);
    // From a saved solution (read from `path`, named in errors): it is the solution shown at once, with no
    // transport. prepare() rebuilds the transport from the saved scene and settings (it is not saved) and the
    // solver continues from the saved radiosity (southwell's by jacobi, as southwell cannot start from a
    // given radiosity). Throws InputError naming the file when the settings cannot be used.
    RadiosityPipeline(SavedSolution saved, const std::string& path, const DisplayOptions& display = {});

    // Builds the transport (form factors, adaptive passes or hierarchical links) and makes the solver; does
    // nothing the second time. Adaptive and hierarchical subdivision change patches() and display().
    void prepare(Progress* progress = nullptr);
    // Whether prepare() has returned: the transport and the solver exist (it can throw after counting a
    // form-factor pass).
    bool prepared() const { return solver_ != nullptr; }
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
    // The patches the solution belongs to (its elements: the meshed scene's, or after prepare the adaptive or
    // hierarchical leaves), or before there is a solution the meshed scene's.
    const PatchMesh& patches() const { return solution_.elements ? *solution_.elements : *loaded_.patches; }
    Subdivision subdivision() const { return subdivision_; }
    // Whether there is a solution to show: after prepare, or opened from a file. Before, the display is a
    // preview: the emission (preview_radiosity) and the emitters' direct light at the vertices.
    bool has_solution() const { return solution_.elements != nullptr; }
    // The solution as it stands (has_solution()): the solver's, or the file's until prepare.
    const Solution& solution() const;
    // Built on first use, so `solve` never pays for it.
    const DisplayMesh& display() const;
    // A display with these options: of the solution (build_solution_display), or before there is one the
    // preview (build_preview_display).
    DisplayMesh build_display(const DisplayOptions& options, Progress* progress = nullptr) const;
    // `display` (built by build_display with `options`) drawn with the solution as it stands: only its light
    // replaced where its geometry and traces still hold (after an edit of the materials' colours or of the
    // sky and sun: no ray is traced), else built again. Returns whether it was built again (new geometry).
    bool redraw_display(DisplayMesh& display, const DisplayOptions& options,
                        Progress* progress = nullptr) const;
    // Builds display() now, reporting the final gather's progress (a render's stage that can take seconds).
    void prepare_display(Progress* progress) const;
    // E per patch of patches(): the radiosity before any light is reflected.
    std::vector<glm::dvec3> preview_radiosity() const;
    // After prepare.
    const Transport& transport() const;
    const Solver& solver() const { return *solver_; }
    const SolverOptions& solver_options() const { return solver_options_; }
    SolverMethod method() const { return method_; }

    // One ray scene over the solution's elements (has_solution()), for everything that traces them after the
    // transport is built (the display, an edit of the sky, sensors): the one the transport's build made where
    // it made one.
    const RayScene& element_rays() const;

    // Emitted, absorbed and escaped power of the solution as it stands (after prepare).
    EnergyBalance energy_balance() const;

    // Linear radiance L = B / π per display vertex for the solution as it stands (black before there is
    // one).
    std::vector<glm::vec3> vertex_radiance() const;

    // The state to save: the scene and the solution, with the display patches' own gather.
    SavedSolution saved_solution() const;

    const WorkCounts& work() const { return work_; }
    const StageSeconds& seconds() const { return seconds_; }

  private:
    TransportSettings transport_settings() const;
    SolutionSettings solution_settings() const;
    // The solution's elements from the transport just built or edited.
    void take_elements();
    // ρ H_d per element: the emitters' light reflected once, by the transport (after prepare).
    std::vector<glm::dvec3> element_direct() const;
    // Opened from a file: the rebuilt elements must be the file's, and the solver starts from its radiosity.
    void continue_from_solution();
    // A fresh solver of the same method and options from the solution as it stands, after an edit of the
    // transport's sources.
    void restart_from_solution();
    // The solver's state changed: solution() copies it again when asked.
    void solver_changed();
    // --subdivision auto: uniform patches or clustering by the scene's faces, then the uniform mesh's size
    // (choose_subdivision), and the patches that subdivision is meshed with.
    void choose_automatic_subdivision();

    PipelineOptions options_;
    std::string opened_path_;  // the saved file the pipeline was opened from, for errors
    Subdivision subdivision_ = Subdivision::automatic;  // the method, once the constructor has chosen it
    LoadedScene loaded_;
    Sky opened_sky_;  // the scene's sky and sun as opened, which an empty edit returns to
    Sun opened_sun_;
    std::shared_ptr<SceneTransport> built_;  // shared with the solution's elements where it owns them
    mutable Solution solution_;
    // Whether solution_ holds the transport's elements' arrays and the solver's state.
    mutable bool elements_current_ = true;
    mutable bool radiosity_current_ = true;
    bool continues_solution_ = false;             // opened from a file: prepare continues from its radiosity
    GatherTable traced_display_gather_;           // the file's, until prepare
    mutable std::optional<DisplayMesh> display_;  // of patches(), once asked for
    mutable std::shared_ptr<const RayScene> element_rays_;  // over element_rays_of_
    mutable std::shared_ptr<const PatchMesh> element_rays_of_;
    mutable std::vector<glm::dvec3> loaded_albedo_;  // of loaded_.patches, for the preview's texel detail
    SolverMethod method_;
    SolverOptions solver_options_;
    std::unique_ptr<Solver> solver_;
    WorkCounts work_;
    StageSeconds seconds_;
};

}  // namespace rad
