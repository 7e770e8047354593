#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "rad/transport/transport_methods.hpp"

namespace rad {

// One transport method of the sweep, run on the furnaces up to `max_faces`.
struct ScalingMethod {
    Subdivision method;
    std::size_t max_faces = kAnySize;
};

// `radiosity bench --scaling`: builtin furnaces (a closed room of tessellated balls, B = E / (1 − ρ) on every
// face) from small to large, solved at the defaults with each of the plan's methods; the crossover compares
// the first two.
struct ScalingPlan {
    std::vector<std::string> faces;  // furnace sizes as builtin:furnace-N spells them: "10k", "1m"
    std::vector<ScalingMethod> methods;
};

// From 1k to 1M faces (1k and 2k for the tests) with the methods `auto` chooses between: the one for any size
// at every size, the others to 100k faces (2k).
ScalingPlan default_scaling_plan(bool quick);

// One furnace solved one way. Seconds are the pipeline's stages: mesh (the scene made and meshed), build
// (form factors, or clusters and links) and solve.
struct ScalingRow {
    std::string scene;
    std::string subdivision;
    std::size_t faces = 0;
    std::size_t patches = 0;   // uniform patches, or base patches
    std::size_t elements = 0;  // what the solution is indexed by: patches, or leaves
    std::size_t links = 0;     // form factors, or links
    std::size_t clusters = 0;  // 0 for uniform
    std::size_t steps = 0;
    std::string solver;
    bool converged = false;
    double mesh_seconds = 0.0, build_seconds = 0.0, solve_seconds = 0.0;
    double seconds() const { return mesh_seconds + build_seconds + solve_seconds; }
    std::size_t peak_bytes = 0;  // peak resident memory of this run (or of the process so far: see notes)
    double furnace_error = 0.0;  // max over elements and channels of |B − E/(1 − ρ)| / (E/(1 − ρ))
    std::string failure;         // why the run stopped, or empty
};

// Where the `faster` method gets faster than the `other`, from the sizes both ran on.
struct Crossover {
    bool found = false;
    std::string text;  // one sentence for the report
};
Crossover scaling_crossover(const std::vector<ScalingRow>& rows, const std::string& faster,
                            const std::string& other);

struct ScalingResults {
    std::string faster, other;  // the methods the crossover compares: the plan's first two
    std::vector<ScalingRow> rows;
    std::vector<std::string> notes;
};

// Throws InputError naming the first size that is not a furnace's, so a bad one is refused before minutes
// of work.
void check_scaling_plan(const ScalingPlan& plan);

// Runs the plan; `row_done` sees the results after each run (the command rewrites its report, so a sweep
// stopped at a large size keeps what it finished), `log` one line per run.
void run_scaling(const ScalingPlan& plan, ScalingResults& results,
                 const std::function<void(const ScalingResults&)>& row_done,
                 const std::function<void(const std::string&)>& log);

}  // namespace rad
