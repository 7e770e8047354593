#pragma once

#include <cstddef>
#include <deque>
#include <glm/vec3.hpp>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/solve/solver.hpp"
#include "viewer/solver_snapshot.hpp"

namespace rad {

// What each of the last solver steps added alone (its bounce), per patch and per display vertex, and the
// plots of every step's residual and unshot power: what the panel shows of the steps taken.
class BounceHistory {
  public:
    // A fresh history, with no bounces and no plots, whose first step is `first_step` (a saved solution
    // continues from its own step count, while the pipeline's solver counts from 0 again).
    void restart(std::size_t first_step = 0);
    // The radiosity the solver starts from (the emission, its first guess, or a saved solution) is the
    // newest light of the first step.
    void add_start(const DisplayMesh& display, std::vector<glm::dvec3> radiosity);
    // A step from `before` to `after`: the light it added, and its report for the plots.
    void add_step(const DisplayMesh& display, std::vector<glm::dvec3> before,
                  const std::vector<glm::dvec3>& after, const StepReport& report);
    // The bounces' vertex colours again, on a new display mesh (smooth or flat).
    void recolour(const DisplayMesh& display);

    // The solver's radiosity one step before the one shown (empty at the start of a history), which the
    // vertices with a gather row take (stepped_vertex_radiance), so they show the bounces of the step too.
    const std::vector<glm::dvec3>& previous_solution() const { return previous_solution_; }
    const std::deque<ViewerRadiance::Colours>& vertex_bounces() const { return vertex_bounces_; }
    std::size_t first_step() const { return first_step_; }
    // The step whose light vertex_bounces() starts with.
    std::size_t first_bounce() const { return first_step_ + dropped_; }
    const std::vector<float>& log_residual() const { return log_residual_; }
    const std::vector<float>& log_unshot() const { return log_unshot_; }

  private:
    // `direct_share`: how much of the emitters' direct light the bounce holds (direct_light_share's rise).
    void add_bounce(const DisplayMesh& display, std::vector<glm::dvec3> bounce, double direct_share);

    // Front: step first_bounce().
    std::deque<std::vector<glm::dvec3>> patch_bounces_;
    std::deque<ViewerRadiance::Colours> vertex_bounces_;
    std::deque<double> direct_share_;
    std::size_t first_step_ = 0;
    std::size_t dropped_ = 0;  // bounces dropped from the front
    std::vector<glm::dvec3> previous_solution_;
    std::vector<float> log_residual_;
    std::vector<float> log_unshot_;
};

}  // namespace rad
