#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "rad/display/gather_table.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// The settings a solution was solved with: enough to rebuild its transport (form factors or links) from the
// saved scene, which is not saved. Methods are stored by their names (subdivision_name, solver_method_name,
// "hemisphere" or "analytic", initial_guess_name); zero tolerances, sizes and rays mean the method's default,
// as in the settings themselves.
struct SavedSettings {
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
struct SavedReport {
    std::uint64_t steps = 0;
    double residual = 0.0;
    std::string status = "converged";  // solver_status_name
    std::string status_message;
};

// A solved scene, as `solve --save` writes it: the scene as loaded (its warnings excepted), the settings,
// the elements the solution is indexed by (as patches) with their A, ρ, E, the solution, what the display
// shows and the direct light it draws at vertices, and the solver's report.
struct SavedSolution {
    SavedSettings settings;
    Scene scene;  // source is settings.scene_source
    PatchMesh patches;
    std::vector<double> area;                       // per element: exposed area
    std::vector<glm::dvec3> reflectance, emission;  // ρ, E = π Le
    std::vector<glm::dvec3> solution;               // B (Solver::solution)
    std::vector<glm::dvec3> display_solution;       // what is shown (Solver::display_solution)
    std::vector<glm::dvec3> direct;                 // ρ H_d: the emitters' light reflected once
                                                    // (DisplayMesh::DirectLight::patch)
    SavedReport report;
    // A hierarchy's display patches' own gather (DisplayMesh::PatchGather's table: a row per display patch,
    // over the elements), so that opening the file does not trace it again; empty where the display has none.
    GatherTable display_gather;

    std::size_t size() const { return patches.size(); }
};

// The file: a 32-byte header, then the payload, all little-endian.
//   0  magic "\x89RADSOL\n" (8 bytes)   8  u32 version   12  u32 0   16  u64 payload bytes
//   24 u64 checksum: 64-bit FNV-1a of the payload
// The payload's layout is in docs/architecture.md ("Saved solutions") and saved_solution.cpp.
inline constexpr std::string_view kSavedSolutionMagic{"\x89RADSOL\n", 8};
inline constexpr std::uint32_t kSavedSolutionVersion = 5;
inline constexpr std::size_t kSavedSolutionHeaderBytes = 32;

// Whether a scene argument names a saved solution rather than a scene: it ends in .radiosity (any case).
bool is_saved_solution_path(const std::filesystem::path& path);

// The whole file's bytes. Throws std::invalid_argument for inconsistent input (array sizes that differ from
// the patch count, a non-finite value), which is a bug of the caller, not bad input.
std::string encode_saved_solution(const SavedSolution& saved);
// Reads what encode_saved_solution wrote. Throws InputError, "NAME: what is wrong" on one line, for a file
// that is not one (wrong magic), another version, a truncated or corrupt file (size, checksum), counts that
// do not fit the bytes left (checked before anything is allocated for them), non-finite or out-of-range
// values, indices out of range and trailing bytes.
SavedSolution decode_saved_solution(std::string_view bytes, const std::string& name);
// 64-bit FNV-1a, the payload's checksum.
std::uint64_t saved_solution_checksum(std::string_view payload);

// Writes through a temporary file renamed into place, so the file appears whole or not at all. Throws
// std::runtime_error when it cannot be written.
void write_saved_solution(const std::filesystem::path& path, const SavedSolution& saved);
// Throws InputError naming the file for a missing, unreadable or non-regular file, and as
// decode_saved_solution does.
SavedSolution read_saved_solution(const std::filesystem::path& path);

}  // namespace rad
