#include "bench/leak_sweep.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "gl/scene_image_renderer.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

std::string room_file(const LeakPlan& plan, const LeakRoom& room) {
    return (std::filesystem::path(plan.folder) / (room.name + ".obj")).string();
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

double energy_error(const EnergyBalance& e) {
    const double in = e.emitted.y + e.outside.y;
    return in > 0.0 ? std::abs(e.imbalance().y) / in : 0.0;
}

}  // namespace

LeakRow run_leak_room(const LeakPlan& plan, const LeakRoom& room, Subdivision subdivision) {
    LeakRow row;
    row.room = room.name;
    row.subdivision = std::string(subdivision_name(subdivision));
    PipelineOptions options;
    options.scene.scene = room_file(plan, room);
    if (room.sky) options.scene.sky = "1";
    options.subdivision.method = row.subdivision;
    const auto start = std::chrono::steady_clock::now();
    try {
        RadiosityPipeline pipeline(options);
        pipeline.solve();
        const std::span<const glm::dvec3> solution = pipeline.solver().solution();
        const Leak leak = measure_leak(pipeline.loaded().scene, pipeline.patches(), solution, room.interior);
        row.elements = solution.size();
        row.inside = leak.inside;
        row.element_leak = leak.ratio();
        row.energy_error = energy_error(pipeline.energy_balance());
        const Image image = SceneImageRenderer(pipeline, false)
                                .render(interior_camera(room.interior), plan.image_size, plan.image_size);
        row.image_leak = image_leak(image, leak.lit_mean);
    } catch (const std::exception& e) {
        row.failure = e.what();
    }
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return row;
}

void check_leak_plan(const LeakPlan& plan) {
    for (const LeakRoom& room : leak_rooms()) {
        const std::string file = room_file(plan, room);
        if (!std::filesystem::is_regular_file(file))
            throw InputError(
                "--leak-dir " + plan.folder + ": no " + room.name +
                ".obj there (the leak suite's rooms are in assets/hard; run from the source tree)");
    }
}

std::vector<LeakRow> run_leaks(const LeakPlan& plan, const std::function<void(const std::string&)>& log) {
    std::vector<LeakRow> rows;
    for (const LeakRoom& room : leak_rooms()) {
        for (Subdivision subdivision : all_subdivisions()) {
            LeakRow row = run_leak_room(plan, room, subdivision);
            log(row.failure.empty()
                    ? format("%8.2f s  ", row.seconds) + row.room + "  " + row.subdivision +
                          format("  elements %.2g", row.element_leak) +
                          format("  image %.2g", row.image_leak) + format("  energy %.2g", row.energy_error)
                    : row.room + "  " + row.subdivision + "  failed: " + row.failure);
            rows.push_back(std::move(row));
        }
    }
    return rows;
}

std::string leak_table(const std::vector<LeakRow>& rows) {
    std::string text =
        "| room | subdivision | elements | inside | leak (elements) | leak (image) | energy error | s |\n"
        "|---|---|---|---|---|---|---|---|\n";
    for (const LeakRow& r : rows) {
        text += "| " + r.room + " | " + r.subdivision + " | ";
        if (!r.failure.empty()) {
            text += "failed: " + r.failure + " | | | | | |\n";
            continue;
        }
        text += std::to_string(r.elements) + " | " + std::to_string(r.inside) + " | " +
                format("%.2g | ", r.element_leak) + format("%.2g | ", r.image_leak) +
                format("%.2g | ", r.energy_error) + format("%.2f |\n", r.seconds);
    }
    text +=
        "\nLeak: the brightest element looking into the closed interior (or the brightest pixel of a view "
        "from inside, as radiosity) over the mean radiosity of the lit elements outside; 0 is right.\n";
    return text;
}

std::string leak_csv(const std::vector<LeakRow>& rows) {
    std::string text =
        "room,subdivision,elements,inside,element_leak,image_leak,energy_error,seconds,failed\n";
    for (const LeakRow& r : rows) {
        char line[512];
        std::snprintf(line, sizeof line, "%s,%s,%zu,%zu,%.6g,%.6g,%.6g,%.6f,%d\n", r.room.c_str(),
                      r.subdivision.c_str(), r.elements, r.inside, r.element_leak, r.image_leak,
                      r.energy_error, r.seconds, r.failure.empty() ? 0 : 1);
        text += line;
    }
    return text;
}

}  // namespace rad
