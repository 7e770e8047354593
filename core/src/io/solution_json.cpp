#include "rad/io/solution_json.hpp"

#include "rad/io/atomic_file.hpp"

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

glm::dvec3 outside_irradiance(const Solution& solution, std::size_t i) {
    return solution.outside.empty() ? glm::dvec3(0.0) : solution.outside[i];
}

json patch_json(const Scene& scene, const Solution& solution, std::size_t i) {
    const Patch& patch = solution.elements->patches[i];
    const glm::dvec3& radiosity = solution.radiosity[i];
    const Surface& surface = scene.surfaces.at(patch.surface);
    return json{{"surface", surface.name},
                {"surface_index", patch.surface},
                {"material", surface.material.name},
                {"area", patch.area},
                // The share other geometry does not cover; radiosity is that of this exposed part.
                {"exposed", solution.area[i] / patch.area},
                {"centroid", triple(patch.centroid)},
                {"normal", triple(patch.normal)},
                {"reflectance", triple(solution.reflectance[i])},
                {"emission", triple(surface.material.emitted_radiosity())},
                // The irradiance from the sky and sun (0 without them).
                {"outside_irradiance", triple(outside_irradiance(solution, i))},
                {"radiosity", triple(radiosity)},
                {"radiance", triple(radiosity / std::numbers::pi)}};
}

json transport_json(const TransportReport& t) {
    json out{{"kind", t.kind},
             {"interaction_name", t.interaction_name},
             {"elements", t.elements},
             {"interactions", t.interactions},
             {"memory_bytes", t.memory_bytes},
             {"rays", t.rays},
             {"seconds", t.seconds},
             {"form_factor_passes", t.form_factor_passes},
             {"notes", t.notes}};
    for (const TransportDetail& d : t.details) {
        if (!std::isfinite(d.value))
            throw std::invalid_argument("solution JSON: " + d.name + " is not finite");
        out[d.name] = d.value;
    }
    return out;
}

json stats_json(const Solution& solution, const SolveStatistics& stats) {
    return json{
        {"patches", solution.size()},
        {"nonzeros", stats.transport.interactions},
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
          {"outside", triple(stats.energy.outside)},
          {"absorbed", triple(stats.energy.absorbed)},
          {"escaped", triple(stats.energy.escaped)},
          {"behind", triple(stats.energy.behind)}}},
        {"transport", transport_json(stats.transport)},
    };
}

}  // namespace

void write_solution_json(const std::string& path, const Scene& scene, const Solution& solution,
                         const SolveStatistics& stats) {
    check_solution_fits(scene, solution);
    if (!std::isfinite(stats.residual))
        throw std::invalid_argument("solution JSON: the residual is not finite");
    const std::string stats_text = stats_json(solution, stats).dump();
    // Streamed a patch at a time: a document of a million patches built in memory first would cost more
    // than the solve's own peak.
    replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error("cannot create " + temporary.string());
        out << "{\"patches\":[";
        for (std::size_t i = 0; i < solution.size(); ++i) {
            if (i > 0) out << ',';
            out << patch_json(scene, solution, i).dump();
        }
        out << "],\"stats\":" << stats_text << "}\n";
        out.flush();
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
    });
}

}  // namespace rad
