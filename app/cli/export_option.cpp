#include "cli/export_option.hpp"

#include <cmath>

#include "cli/number_checks.hpp"
#include "pipeline/radiosity_pipeline.hpp"
#include "rad/io/output_path.hpp"
#include "rad/io/scene_export.hpp"
#include "rad/util/error.hpp"
#include "rad/util/file_names.hpp"

namespace rad {

void add_exposure_option(CLI::App& command, double& exposure, const std::string& help) {
    command.add_option("--exposure", exposure, help)
        ->check(finite_range(-kLargestExposure, kLargestExposure))
        ->capture_default_str();
}

void add_exposure_option(CLI::App& command, Exposure& exposure, const std::string& help) {
    const CLI::Validator ev = finite_range(-kLargestExposure, kLargestExposure);
    command
        .add_option_function<std::string>(
            "--exposure",
            [&exposure](const std::string& value) {
                exposure.automatic = value == "auto";
                if (!exposure.automatic) exposure.ev = std::stod(value);
            },
            help)
        ->check(CLI::Validator(
            [ev](std::string& value) { return value == "auto" ? std::string() : ev(value); }, "auto|EV"))
        ->default_str("auto");
}

void add_export_option(CLI::App& command, std::vector<std::string>& paths) {
    command
        .add_option("--export", paths,
                    "Also write the solved scene's mesh with its colours: .ply (sRGB vertex colours and "
                    "linear radiance), .gltf or .glb (COLOR_0 and linear _RADIANCE); repeatable")
        ->type_name("FILE");
}

void check_export_paths(const std::vector<std::string>& paths) {
    for (const std::string& path : paths) {
        if (!export_format(path)) {
            const std::string ext = lowercase_extension(path);
            throw InputError("--export " + path + ": " +
                             (ext.empty() ? "no extension" : "unknown export format '" + ext + "'") +
                             " (use .ply, .gltf or .glb)");
        }
        require_output_folder("export_path", path);
    }
}

void write_exports(const std::vector<std::string>& paths, const RadiosityPipeline& pipeline, double exposure,
                   std::ostream& out) {
    if (paths.empty()) return;
    const std::vector<glm::vec3> radiance = pipeline.vertex_radiance();
    for (const std::string& path : paths) {
        export_scene(path, pipeline.display(), radiance, ExportOptions{.exposure = exposure});
        out << "wrote " << path << '\n';
    }
}

}  // namespace rad
