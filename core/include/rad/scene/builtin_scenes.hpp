#pragma once

#include <string>
#include <vector>

#include "rad/scene/scene.hpp"

namespace rad {

// Names accepted after `builtin:`, each with a one-line description.
struct BuiltinSceneInfo {
    std::string name;
    std::string description;
};
const std::vector<BuiltinSceneInfo>& builtin_scenes();

// Throws InputError listing the available names when `name` is not one of them.
Scene make_builtin_scene(const std::string& name);

Scene make_cornell_box();
// The Cornell box closed by a front wall, every surface but the light white with ρ = 0.95: high albedo.
// The light is the published one dimmed tenfold.
Scene make_white_room();
// A closed unit cube seen from inside: the top face emits E = 1 (Le = 1/π), every face has ρ = 0.5.
Scene make_cube();
// Two unit squares facing each other at distance 1; the lower one emits E = 1, both have ρ = 0.5.
Scene make_parallel_squares();
// Two unit squares sharing an edge at a right angle, facing each other; the floor emits E = 1, ρ = 0.5.
Scene make_perpendicular_squares();

}  // namespace rad
