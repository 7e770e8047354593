#pragma once

#include <string>

#include "rad/scene/scene.hpp"

namespace rad {

// SCENE as the command line takes it: builtin:NAME, or a path to .obj (with its .mtl), .ply, .gltf or .glb.
// Throws InputError, naming the file and line or element, for anything it cannot take.
Scene load_scene(const std::string& spec);

Scene load_obj(const std::string& path);
Scene load_ply(const std::string& path);
// glTF 2.0, text (.gltf: buffers and images external in its folder, or embedded as data: URIs) or binary
// (.glb): triangles through the node hierarchy, materials (base colour and emission, textures as their mean),
// the first perspective camera, and KHR_lights_punctual point and spot lights as small emitting spheres.
Scene load_gltf(const std::string& path);

}  // namespace rad
