#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <string>

#include "rad/form_factors.hpp"
#include "rad/patches.hpp"
#include "rad/radiosity_system.hpp"
#include "rad/scene.hpp"

namespace rad {

// The statistics `radiosity solve --json` writes beside the per-patch results.
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
    FormFactorReport form_factors;
};

// Writes the DESIGN.md `solve --json` document: {"patches": [{"surface", "material", "area", "centroid",
// "normal", "reflectance", "emission" (E = π Le), "radiosity", and also "radiance" (B / π)}], "stats":
// {"patches", "nonzeros", "iterations", "residual", "converged", "seconds": {"mesh", "form_factors",
// "solve"}, "peak_memory_bytes", and also "solver", "status", "status_message", "tolerance", "energy",
// "form_factor_report"}}. It goes to a temporary file in the same folder, renamed into place when complete,
// so no partial file is ever left behind. Throws std::runtime_error when the file cannot be written and
// std::invalid_argument for a non-finite value (JSON has none).
void write_solution_json(const std::string& path, const Scene& scene, const PatchMesh& patches,
                         const RadiositySystem& system, std::span<const glm::dvec3> radiosity,
                         const SolveStatistics& stats);

}  // namespace rad
