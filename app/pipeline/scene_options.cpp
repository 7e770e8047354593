#include "pipeline/scene_options.hpp"

#include <cmath>
#include <iostream>
#include <optional>

#include "pipeline/outside_light_options.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"

namespace rad {

LoadedScene load_scene_only(const SceneOptions& options) {
    // The options are read first, so a mistyped one is reported before a long load.
    const std::optional<Sky> sky = options.sky.empty() ? std::nullopt : std::optional(parse_sky(options.sky));
    const std::optional<Sun> sun = options.sun.empty() ? std::nullopt : std::optional(parse_sun(options.sun));
    LoadedScene loaded;
    loaded.scene = load_scene(options.scene);
    if (sky) loaded.scene.sky = *sky;
    if (sun) loaded.scene.sun = *sun;
    if (has_outside_light(loaded.scene))
        std::erase(loaded.scene.warnings, no_emitter_warning(loaded.scene.source));
    for (const std::string& w : loaded.scene.warnings) std::cerr << "radiosity: warning: " << w << '\n';
    return loaded;
}

void mesh_loaded(LoadedScene& loaded, const SceneOptions& options, double default_scale) {
    loaded.patch_size =
        options.patch_size > 0.0 ? options.patch_size : default_scale * default_patch_size(loaded.scene);
    MeshingOptions meshing;
    meshing.patch_size = loaded.patch_size;
    loaded.patches = std::make_shared<const PatchMesh>(build_patches(loaded.scene, meshing));
}

LoadedScene load_and_mesh(const SceneOptions& options, double default_scale) {
    LoadedScene loaded = load_scene_only(options);
    mesh_loaded(loaded, options, default_scale);
    return loaded;
}

}  // namespace rad
