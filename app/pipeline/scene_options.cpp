#include "pipeline/scene_options.hpp"

#include <cmath>
#include <iostream>

#include "cli/number_checks.hpp"
#include "rad/scene/scene_loader.hpp"

namespace rad {

void add_scene_options(CLI::App& command, SceneOptions& options) {
    command
        .add_option(
            "scene", options.scene,
            "Scene: a .obj (with its .mtl) or .ply file, or builtin:NAME (cornell, white-room, cube, "
            "parallel, perpendicular, furnace, or furnace-N: a closed room of balls of about N faces, "
            "e.g. furnace-100k, furnace-1m, where B = 2 everywhere); render and view also take a saved "
            "solution, FILE.radiosity")
        ->capture_default_str();
    command
        .add_option("--patch-size", options.patch_size,
                    "Largest patch edge, in scene units (default: a sixteenth of the scene's largest extent)")
        ->check(positive_number());
}

LoadedScene load_scene_only(const SceneOptions& options) {
    LoadedScene loaded;
    loaded.scene = load_scene(options.scene);
    for (const std::string& w : loaded.scene.warnings) std::cerr << "radiosity: warning: " << w << '\n';
    return loaded;
}

void mesh_loaded(LoadedScene& loaded, const SceneOptions& options, double default_scale) {
    loaded.patch_size =
        options.patch_size > 0.0 ? options.patch_size : default_scale * default_patch_size(loaded.scene);
    MeshingOptions meshing;
    meshing.patch_size = loaded.patch_size;
    loaded.patches = build_patches(loaded.scene, meshing);
}

LoadedScene load_and_mesh(const SceneOptions& options, double default_scale) {
    LoadedScene loaded = load_scene_only(options);
    mesh_loaded(loaded, options, default_scale);
    return loaded;
}

}  // namespace rad
