#pragma once

#include <CLI/CLI.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "pipeline/exposure.hpp"

namespace rad {

class RadiosityPipeline;

// --export FILE, repeatable: the solved scene's display mesh with its colours as .ply, .gltf or .glb (see
// rad/scene_export.hpp).
void add_export_option(CLI::App& command, std::vector<std::string>& paths);
// The largest |exposure| accepted, so 2^exposure stays a finite float.
constexpr double kLargestExposure = 100.0;

// --exposure EV: a number in [-100, 100], so 2^exposure stays a finite float. `help` says what it affects.
void add_exposure_option(CLI::App& command, double& exposure, const std::string& help);

// --exposure auto|EV, auto by default.
void add_exposure_option(CLI::App& command, Exposure& exposure, const std::string& help);

// Refuses an unknown extension or a missing folder with an InputError naming --export, before long work.
void check_export_paths(const std::vector<std::string>& paths);

// Writes the pipeline's display mesh and radiance to every path, the colours at this exposure, printing
// "wrote FILE" for each.
void write_exports(const std::vector<std::string>& paths, const RadiosityPipeline& pipeline, double exposure,
                   std::ostream& out);

}  // namespace rad
