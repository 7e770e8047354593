#include "pipeline/scene_options.hpp"

#include <cmath>
#include <iostream>
#include <optional>

#include "cli/number_checks.hpp"
#include "pipeline/outside_light_options.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/scene_loader.hpp"

namespace rad {

namespace {

// The built-in scenes' names from their list, so the help never leaves one out.
std::string scene_help() {
    std::string names;
    for (const BuiltinSceneInfo& scene : builtin_scenes()) names += scene.name + ", ";
    return "Scene: a .obj (with its .mtl), .ply, .gltf or .glb file, or builtin:NAME (" + names +
           "or furnace-N: a closed room of balls of about N faces, e.g. furnace-100k, furnace-1m, where "
           "B = 2 everywhere); render and view also take a saved solution, FILE.radiosity";
}

}  // namespace

void add_scene_options(CLI::App& command, SceneOptions& options) {
    command.add_option("scene", options.scene, scene_help())->capture_default_str();
    command
        .add_option("--patch-size", options.patch_size,
                    "Largest patch edge, in scene units (default: a sixteenth of the scene's largest extent)")
        ->check(positive_number());
    command.add_option(
        "--sky", options.sky,
        "Light from a sky at infinity, met by every ray that leaves the scene: R,G,B (or L) is a "
        "uniform radiance; overcast,L (or overcast,R,G,B) the CIE overcast sky of that zenith "
        "radiance, +y up; none");
    command.add_option(
        "--sun", options.sun,
        "A distant sun with shadows: X,Y,Z,E (or X,Y,Z,R,G,B), the direction toward it and the "
        "irradiance on a plane facing it; none");
}

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
    loaded.patches = build_patches(loaded.scene, meshing);
}

LoadedScene load_and_mesh(const SceneOptions& options, double default_scale) {
    LoadedScene loaded = load_scene_only(options);
    mesh_loaded(loaded, options, default_scale);
    return loaded;
}

}  // namespace rad
