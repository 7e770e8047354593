#include "bench/scaling_report.hpp"

#include <cstdio>

namespace rad {

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace

std::string scaling_table(const ScalingResults& results) {
    std::string text =
        "| scene | subdivision | faces | patches | elements (leaves) | links | clusters | solver (steps) | "
        "mesh s "
        "| build s | solve s | total s | peak MB | furnace error |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const ScalingRow& r : results.rows) {
        text += "| " + r.scene + " | " + r.subdivision + " | ";
        if (!r.failure.empty()) {
            text += "failed: " + r.failure +
                    format(" (peak %.0f MB) | | | | | | | | | | | |\n", double(r.peak_bytes) / 1e6);
            continue;
        }
        text += std::to_string(r.faces) + " | " + std::to_string(r.patches) + " | " +
                std::to_string(r.elements) + " | " + std::to_string(r.links) + " | " +
                std::to_string(r.clusters) + " | " + r.solver + " (" + std::to_string(r.steps) +
                (r.converged ? "" : ", not converged") + ") | " + format("%.2f | ", r.mesh_seconds) +
                format("%.2f | ", r.build_seconds) + format("%.2f | ", r.solve_seconds) +
                format("%.2f | ", r.seconds()) + format("%.0f | ", double(r.peak_bytes) / 1e6) +
                format("%.2g |\n", r.furnace_error);
    }
    text += "\nCrossover: " + scaling_crossover(results.rows, results.faster, results.other).text + ".\n";
    for (const std::string& note : results.notes) text += "- " + note + "\n";
    return text;
}

std::string scaling_csv(const ScalingResults& results) {
    std::string text =
        "scene,subdivision,faces,patches,elements,links,clusters,solver,steps,converged,mesh_s,build_s,solve_"
        "s,"
        "total_s,peak_bytes,furnace_error,failed\n";
    for (const ScalingRow& r : results.rows) {
        char line[512];
        std::snprintf(
            line, sizeof line, "%s,%s,%zu,%zu,%zu,%zu,%zu,%s,%zu,%d,%.6f,%.6f,%.6f,%.6f,%zu,%.6g,%d\n",
            r.scene.c_str(), r.subdivision.c_str(), r.faces, r.patches, r.elements, r.links, r.clusters,
            r.solver.c_str(), r.steps, r.converged ? 1 : 0, r.mesh_seconds, r.build_seconds, r.solve_seconds,
            r.seconds(), r.peak_bytes, r.furnace_error, r.failure.empty() ? 0 : 1);
        text += line;
    }
    return text;
}

}  // namespace rad
