#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <string>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"
#include "rad/solve/solution.hpp"
#include "rad/transport/transport.hpp"

namespace rad {

// The statistics the solution JSON holds beside the per-patch results.
struct SolveStatistics {
    std::string solver;
    std::size_t iterations = 0;
    double residual = 0.0;
    double tolerance = 0.0;
    bool converged = false;
    std::string status;          // solver_status_name
    std::string status_message;  // why it stopped
    double mesh_seconds = 0.0;
    double form_factor_seconds = 0.0;
    double solve_seconds = 0.0;
    std::size_t peak_memory_bytes = 0;
    EnergyBalance energy;
    TransportReport transport;
};

// Writes the solution document (the schema of docs/architecture.md, "Solution JSON"): {"patches":
// [{"surface", "material", "area", "centroid", "normal", "reflectance", "emission" (E = π Le), "radiosity",
// and also "radiance" (B / π)}], "stats":
// {"patches", "nonzeros", "iterations", "residual", "converged", "seconds": {"mesh", "form_factors",
// "solve"}, "peak_memory_bytes", and also "solver", "status", "status_message", "tolerance", "energy",
// "transport" (kind, elements, interactions, memory_bytes, rays, seconds, form_factor_passes, notes and
// the method's details)}}; "nonzeros" is the transport's interactions: form factors, or links. It goes to a
// temporary file in the same folder, renamed into place when complete, so no partial file is ever left
// behind. Throws std::runtime_error when the file cannot be written and std::invalid_argument for a
// non-finite value (JSON has none).
// The patches are the solution's elements, with their radiosity B (Solution::radiosity).
void write_solution_json(const std::string& path, const Scene& scene, const Solution& solution,
                         const SolveStatistics& stats);

}  // namespace rad
