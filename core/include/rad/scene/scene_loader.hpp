#pragma once

#include <string>

#include "rad/scene/scene.hpp"

namespace rad {

// SCENE as the command line takes it: builtin:NAME, or a path to .obj (with its .mtl) or .ply.
// Throws InputError, naming the file and line or element, for anything it cannot take.
Scene load_scene(const std::string& spec);

Scene load_obj(const std::string& path);
Scene load_ply(const std::string& path);

}  // namespace rad
