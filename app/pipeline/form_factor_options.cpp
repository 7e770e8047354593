#include "pipeline/form_factor_options.hpp"

namespace rad {

FormFactorOptions form_factor_options_for(const FormFactorOptions& options, const LoadedScene& loaded) {
    FormFactorOptions out = options;
    out.patch_size = loaded.patch_size;
    out.emitting_surfaces = emitting_surfaces(loaded.scene);
    out.emitted_luminance = emitted_luminance(loaded.scene, out.emitting_surfaces);
    out.count_patches_at = [&scene = loaded.scene](double patch_size) {
        return count_patches(scene, patch_size);
    };
    return out;
}

}  // namespace rad
