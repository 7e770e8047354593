#pragma once

#include <memory>
#include <string>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// The options every command that loads a scene shares.
struct SceneOptions {
    std::string scene = "builtin:cornell";
    double patch_size = 0.0;  // 0: the scene's default
    std::string sky;  // --sky as given (parse_sky); empty: the scene's own (none unless the file has one)
    std::string sun;  // --sun as given (parse_sun); empty: the scene's own
};

struct LoadedScene {
    Scene scene;
    std::shared_ptr<const PatchMesh> patches;  // shared with the solutions over them
    double patch_size = 0.0;
};

// Loads and meshes the scene, with the sky and sun of the options, printing its warnings to stderr. Without
// --patch-size the patch size is default_scale × the scene's default. Throws InputError for bad input.
LoadedScene load_and_mesh(const SceneOptions& options, double default_scale = 1.0);

// The two halves of load_and_mesh: the scene alone (no patches yet), then its patches.
LoadedScene load_scene_only(const SceneOptions& options);
void mesh_loaded(LoadedScene& loaded, const SceneOptions& options, double default_scale);

}  // namespace rad
