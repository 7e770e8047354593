#pragma once

// The command line's options of every command that solves a scene (solve, render, view), registered with
// CLI11 into the option values the pipeline reads (app/pipeline/*_options.hpp).

#include <CLI/CLI.hpp>
#include <string>

#include "pipeline/radiosity_pipeline.hpp"

namespace rad {

// All of the below, on one command.
void add_pipeline_options(CLI::App& command, PipelineOptions& options);

// A saved solution (`saved`, for the message) is solved already: the options add_pipeline_options registers
// (the scene excepted) are refused with an InputError naming the first one given on `command`, rather than
// ignored, so nobody believes they took effect.
void refuse_solving_options(const CLI::App& command, const std::string& saved);

// The scene (positional), --patch-size, --sky, --sun.
void add_scene_options(CLI::App& command, SceneOptions& options);

// --ff hemisphere|analytic, --rays N, --seed S, --threads N, --max-memory SIZE (512M, 4G: powers of 1024),
// --reciprocity, --normalize-rows. --threads limits TBB, and so every parallel stage of the process, from
// the moment it is parsed.
void add_form_factor_options(CLI::App& command, FormFactorOptions& options);

// --solver, --tol, --bounces, --initial, --sor.
void add_solver_options(CLI::App& command, SolverCommandOptions& options);

// --subdivision (the methods' table's names and help), --refine-tol, --min-patch-size.
void add_subdivision_options(CLI::App& command, SubdivisionOptions& options);

}  // namespace rad
