#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "pipeline/radiosity_pipeline.hpp"
#include "rad/display/display_mesh.hpp"

namespace rad {

// What the viewer has asked its worker for and the worker has not started, and the one rule for which
// command runs next. It holds no lock: the worker guards it with its own mutex.
class WorkerCommands {
  public:
    // Loads (another scene, or the same at another patch size or form-factor method) and recomputes.
    struct Rebuild {
        PipelineOptions options;
        std::size_t steps = 0;  // asked for with it, taken once it has opened
    };
    struct ColourModeSwitch {
        ColourMode mode = ColourMode::smooth;
    };
    // A fresh solver with this method and tolerance, on the same form factors.
    struct Reset {
        std::string method;
        double tolerance = 0.0;
        // B = E whatever --initial says (the panel's reset); else --initial's guess.
        bool from_emission = false;
    };
    struct MaterialEdit {
        std::string name;
        glm::dvec3 reflectance{0.0};
        glm::dvec3 emitted_radiance{0.0};
    };
    struct OutsideLight {
        std::string sky;
        std::string sun;
    };
    struct Write {
        std::string path;
        double exposure = 0.0;
    };
    struct Step {};

    // The rule: the waiting command of the earliest kind in this list runs next, the oldest of its kind
    // first. A new scene comes first, as it changes what every other command works on; a colour switch and a
    // reset come before the steps, so the steps asked after them are taken on what they made.
    using Command = std::variant<Rebuild, ColourModeSwitch, Reset, MaterialEdit, OutsideLight, Write, Step>;

    // Waits behind the others by its kind: a rebuild, a colour mode, a reset and an outside light replace
    // the one of their kind waiting; an edit replaces the waiting edit of its material; writes each wait
    // their turn; a step adds one to the steps asked for. A rebuild keeps the one running to start again
    // should its own file not open; a reset drops the steps asked for and pauses the run.
    void add(Command command);
    void add_steps(std::size_t count);
    void set_running(bool running) { running_ = running; }
    // Drops the steps asked for and not taken, and pauses the run (a cancel, a failure, a finished solver).
    void stop_stepping();
    // Steps wait for a solver that can take them: those asked for before the solver exists wait for it
    // (scripted runs rely on that).
    void set_can_step(bool can_step) { can_step_ = can_step; }

    bool has_next() const { return next().has_value(); }
    // Removes and returns the command that runs next (only when has_next()); a rebuild becomes the one
    // running.
    Command take_next();
    // The command taken last has ended; `completed`: it ran to its end, so a rebuild it cut short need not
    // run again.
    void end_job(bool completed);
    // The rebuild running did not open its file, so nothing changed: the rebuild it cut short waits again,
    // unless a newer one waits already. True if it does.
    bool restart_interrupted();
    // The rebuild running has opened its scene: what it cut short is gone for good.
    void opened() { interrupted_rebuild_.reset(); }

    bool running() const { return running_; }
    std::size_t steps() const { return steps_; }

  private:
    // The place in waiting_ of the command that runs next, waiting_.size() for a step, or nothing.
    std::optional<std::size_t> next() const;

    std::vector<Command> waiting_;  // steps are counted instead
    std::size_t steps_ = 0;
    bool running_ = false;   // steps until the solver finishes
    bool can_step_ = false;  // a solver exists and has not finished
    std::optional<Rebuild> current_rebuild_;
    std::optional<Rebuild> interrupted_rebuild_;  // cut short by a newer one
};

}  // namespace rad
