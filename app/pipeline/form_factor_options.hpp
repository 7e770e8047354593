#pragma once

#include "pipeline/scene_options.hpp"
#include "rad/transport/uniform/form_factors.hpp"

namespace rad {

// `options` with what only the loaded scene knows: its patch size and patch count at other sizes, so that a
// pass over the memory budget names a --patch-size that fits. `loaded` must outlive the result.
FormFactorOptions form_factor_options_for(const FormFactorOptions& options, const LoadedScene& loaded);

}  // namespace rad
