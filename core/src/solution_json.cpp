#include "rad/solution_json.hpp"

#include "rad/atomic_file.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <stdexcept>

namespace rad {

namespace {

using nlohmann::json;

json triple(const glm::dvec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        throw std::invalid_argument("solution JSON: a value is not finite");
    }
    return json::array({v.x, v.y, v.z});
}

json patch_json(const Scene& scene, const PatchMesh& patches, const RadiositySystem& system,
                std::span<const glm::dvec3> radiosity, std::size_t i) {
    const Patch& patch = patches.patches[i];
    const Surface& surface = scene.surfaces.at(patch.surface);
    return json{{"surface", surface.name},
                {"surface_index", patch.surface},
                {"material", surface.material.name},
                {"area", patch.area},
                // The share other geometry does not cover; radiosity is that of this exposed part.
                {"exposed", system.area[i] / patch.area},
                {"centroid", triple(patch.centroid)},
                {"normal", triple(patch.normal)},
                {"reflectance", triple(system.reflectance[i])},
                {"emission", triple(system.emission[i])},
                {"radiosity", triple(radiosity[i])},
                {"radiance", triple(radiosity[i] / std::numbers::pi)}};
}

json stats_json(const RadiositySystem& system, const SolveStatistics& stats) {
    const FormFactorReport& ff = stats.form_factors;
    return json{
        {"patches", system.size()},
        {"nonzeros", system.form_factors.nonzeros()},
        {"iterations", stats.iterations},
        {"residual", stats.residual},
        {"converged", stats.converged},
        {"seconds",
         {{"mesh", stats.mesh_seconds},
          {"form_factors", stats.form_factor_seconds},
          {"solve", stats.solve_seconds}}},
        {"peak_memory_bytes", stats.peak_memory_bytes},
        {"solver", stats.solver},
        {"status", stats.status},
        {"status_message", stats.status_message},
        {"tolerance", stats.tolerance},
        {"energy",
         {{"emitted", triple(stats.energy.emitted)},
          {"absorbed", triple(stats.energy.absorbed)},
          {"escaped", triple(stats.energy.escaped)}}},
        {"form_factor_report",
         {{"seconds", ff.seconds},
          {"memory_bytes", ff.memory_bytes},
          {"rays", ff.rays},
          {"escaped_ray_fraction", ff.escaped_ray_fraction},
          {"max_reciprocity_error", ff.max_reciprocity_error},
          {"min_row_sum", ff.min_row_sum},
          {"max_row_sum", ff.max_row_sum}}},
    };
}

}  // namespace

void write_solution_json(const std::string& path, const Scene& scene, const PatchMesh& patches,
                         const RadiositySystem& system, std::span<const glm::dvec3> radiosity,
                         const SolveStatistics& stats) {
    if (patches.size() != system.size() || radiosity.size() != system.size()) {
        throw std::invalid_argument("solution JSON: patches, system and radiosity differ in size");
    }
    json document;
    json& patch_list = document["patches"] = json::array();
    for (std::size_t i = 0; i < patches.size(); ++i) {
        patch_list.push_back(patch_json(scene, patches, system, radiosity, i));
    }
    document["stats"] = stats_json(system, stats);
    if (!std::isfinite(stats.residual))
        throw std::invalid_argument("solution JSON: the residual is not finite");
    write_file_atomically(path, document.dump() + "\n");
}

}  // namespace rad
