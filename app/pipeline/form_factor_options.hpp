#pragma once

#include <CLI/CLI.hpp>

#include "pipeline/scene_options.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// Registers the form-factor options on `command`: --ff hemisphere|analytic, --rays N, --seed S,
// --threads N, --max-memory SIZE (512M, 4G: powers of 1024), --reciprocity, --normalize-rows. --threads
// limits TBB, and so every parallel stage of the process, from the moment it is parsed.
void add_form_factor_options(CLI::App& command, FormFactorOptions& options);

// `options` with what only the loaded scene knows: its patch size and patch count at other sizes, so that a
// pass over the memory budget names a --patch-size that fits. `loaded` must outlive the result.
FormFactorOptions form_factor_options_for(const FormFactorOptions& options, const LoadedScene& loaded);

}  // namespace rad
