#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// The settings a solution was solved with: enough to rebuild its transport (form factors or links) from its
// scene. Methods are stored by their names (subdivision_name, solver_method_name, "hemisphere" or
// "analytic", initial_guess_name); zero tolerances, sizes and rays mean the method's default, as in the
// settings themselves.
struct SolutionSettings {
    std::string scene_source;  // the scene's file path or builtin:NAME, for messages
    double patch_size = 0.0;   // the size the (base) patches were made with, never 0
    std::string subdivision = "uniform";
    double refine_tolerance = 0.0;
    double min_patch_size = 0.0;
    std::string form_factor_method = "hemisphere";
    std::int64_t rays = 0;
    std::uint64_t seed = 1;
    bool reciprocity = false;
    bool normalize_rows = false;
    std::string solver = "jacobi";  // the method that ran (never "auto")
    double tolerance = 1e-5;
    std::uint64_t bounces = 1000;  // the step limit in sweeps (a southwell sweep is a shot per element)
    std::string initial = "emission";
    double relaxation = 1.0;
};

// The solver's last report.
struct SolutionReport {
    std::uint64_t steps = 0;
    double residual = 0.0;
    std::string status = "converged";  // solver_status_name
    std::string status_message;
};

// What a solve produces and a saved file holds, whichever it came from: the elements the solution is indexed
// by (as patches: each names its surface and face), per element its exposed area A, reflectance ρ, what its
// radiosity starts from (E, plus ρ H_out under a sky or sun), ρ H_d (the emitters' light reflected once), the
// irradiance H_out from the sky and sun (empty without them), the radiosity B and what is shown of it, the
// settings and the solver's report. The elements are shared: a
// solution copied for a file or a display does not copy the mesh.
struct Solution {
    SolutionSettings settings;
    std::shared_ptr<const PatchMesh> elements;
    std::vector<double> area;
    std::vector<glm::dvec3> reflectance, emission, direct;
    std::vector<glm::dvec3> outside;          // H_out per element, or empty: no sky or sun
    std::vector<glm::dvec3> radiosity;        // B (Solver::solution)
    std::vector<glm::dvec3> shown_radiosity;  // what is shown (Solver::display_solution)
    SolutionReport report;

    std::size_t size() const { return elements ? elements->size() : 0; }
};

// Throws std::invalid_argument, naming what differs, when `solution` cannot be a solution of `scene`: no
// elements, a per-element array of another size (outside: empty or one per element), or an element on a
// surface or face the scene does not have.
void check_solution_fits(const Scene& scene, const Solution& solution);

}  // namespace rad
