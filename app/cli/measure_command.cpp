// `radiosity measure SCENE|FILE.radiosity --points FILE [--out FILE.csv]`: the illuminance at sensors. A
// scene is solved first (with solve's options); a saved solution is measured as saved, with no form factors
// and no solve. Writes one CSV row per sensor (to --out, or to the standard output): the point, its
// direction, the illuminance in lux, the irradiance per channel in W/m², and under an overcast sky the
// daylight factor.
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/sensors_file.hpp"
#include "cli/solving_options.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/io/atomic_file.hpp"
#include "rad/io/output_path.hpp"
#include "rad/io/saved_solution.hpp"
#include "rad/measure/sensor_irradiance.hpp"
#include "rad/util/error.hpp"
#include "text/progress_bar.hpp"

namespace rad {

namespace {

struct MeasureOptions {
    PipelineOptions pipeline;
    std::string points;
    std::string out;
};

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// The CSV of the sensors' light; the daylight factor where the sky is the CIE overcast sky: the sensor's
// illuminance from everything but the sun over the unobstructed sky's on a horizontal plane.
std::string sensors_csv(const std::vector<Sensor>& sensors, const std::vector<SensorIrradiance>& light,
                        const Sky& sky) {
    const bool daylight = sky.kind == Sky::Kind::overcast;
    const double unobstructed = illuminance_lux(unobstructed_sky_irradiance(sky));
    std::ostringstream csv;
    csv << "x,y,z,dx,dy,dz,illuminance_lux,irradiance_r,irradiance_g,irradiance_b"
        << (daylight ? ",daylight_factor_percent" : "") << '\n';
    for (std::size_t k = 0; k < sensors.size(); ++k) {
        const Sensor& s = sensors[k];
        const glm::dvec3 e = light[k].total();
        for (double v : {s.point.x, s.point.y, s.point.z, s.direction.x, s.direction.y, s.direction.z})
            csv << number(v) << ',';
        csv << number(illuminance_lux(e)) << ',' << number(e.x) << ',' << number(e.y) << ',' << number(e.z);
        if (daylight) csv << ',' << number(100.0 * illuminance_lux(e - light[k].sun) / unobstructed);
        csv << '\n';
    }
    return csv.str();
}

int run_measure(const MeasureOptions& options, const CLI::App& command) {
    const std::string& scene = options.pipeline.scene.scene;
    const bool saved = is_saved_solution_path(scene);
    if (saved) refuse_solving_options(command, scene);
    if (!options.out.empty()) require_output_folder("csv_path", options.out);
    const std::vector<Sensor> sensors = read_sensors_file(options.points);
    std::unique_ptr<RadiosityPipeline> pipeline =
        saved ? std::make_unique<RadiosityPipeline>(read_saved_solution(scene), scene)
              : std::make_unique<RadiosityPipeline>(options.pipeline);
    Progress progress;
    std::vector<SensorIrradiance> light;
    {
        const ProgressBar bar(progress);
        if (!pipeline->has_solution()) pipeline->solve(&progress);
        light = sensor_irradiance(pipeline->loaded().scene, pipeline->solution(), pipeline->element_rays(),
                                  sensors, pipeline->solution().settings.seed, &progress);
    }
    const std::string csv = sensors_csv(sensors, light, pipeline->loaded().scene.sky);
    if (options.out.empty()) {
        std::cout << csv;
        return 0;
    }
    write_file_atomically(options.out, csv);
    std::cout << "wrote " << options.out << " (" << sensors.size() << " sensors)\n";
    return 0;
}

}  // namespace

CommandRunner add_measure_command(CLI::App& app) {
    auto options = std::make_shared<MeasureOptions>();
    CLI::App* measure = app.add_subcommand(
        "measure", "Solve SCENE (or take a saved .radiosity solution) and write the illuminance at sensors");
    add_pipeline_options(*measure, options->pipeline);
    measure
        ->add_option(
            "--points", options->points,
            "A file of sensors, one 'x y z dx dy dz' per line (the point and the direction it faces; "
            "# comments)")
        ->required();
    measure->add_option(
        "--out", options->out,
        "Where to write the CSV (default: the standard output): x,y,z,dx,dy,dz,illuminance_lux,"
        "irradiance_r,irradiance_g,irradiance_b, and daylight_factor_percent under --sky "
        "overcast");
    return [measure, options]() -> int {
        if (!*measure) return -1;
        return run_measure(*options, *measure);
    };
}

}  // namespace rad
