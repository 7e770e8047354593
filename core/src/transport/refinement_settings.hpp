#pragma once

// The settings hierarchical radiosity and clustering share, checked alike. Private to the library.

#include <cmath>

#include "rad/util/error.hpp"

namespace rad {

// Throws SettingError for a tolerance that is not positive, a negative smallest element, or shadow rays per
// link outside [1, 4096].
inline void check_refinement_settings(double tolerance, double min_patch_size, int visibility_rays) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        throw SettingError("refine_tolerance", "must be a positive number");
    if (!(min_patch_size >= 0.0) || !std::isfinite(min_patch_size))
        throw SettingError("min_patch_size", "must be a non-negative number");
    if (visibility_rays < 1 || visibility_rays > 4096)
        throw SettingError("visibility_rays", "shadow rays per link must lie in [1, 4096]");
}

}  // namespace rad
