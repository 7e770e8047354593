#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "rad/scene/scene.hpp"

namespace rad {

// Names accepted after `builtin:`, each with a one-line description.
struct BuiltinSceneInfo {
    std::string name;
    std::string description;
};
const std::vector<BuiltinSceneInfo>& builtin_scenes();

// Throws InputError listing the available names when `name` is not one of them. Besides the listed names it
// takes furnace-N, a furnace of about N faces (see make_furnace).
Scene make_builtin_scene(const std::string& name);

Scene make_cornell_box();
// The Cornell box closed by a front wall, every surface but the light white with ρ = 0.95: high albedo.
// The light is the published one dimmed tenfold.
Scene make_white_room();
// The Cornell box (its materials, blocks and camera; the ceiling whole) lit by 12 x 12 lamps of 20 mm, 10 mm
// under the ceiling, facing down, with the published light's power between them.
Scene make_many_lights_box();
// A closed unit cube seen from inside: the top face emits E = 1 (Le = 1/π), every face has ρ = 0.5.
Scene make_cube();
// Two unit squares facing each other at distance 1; the lower one emits E = 1, both have ρ = 0.5.
Scene make_parallel_squares();
// Two unit squares sharing an edge at a right angle, facing each other; the floor emits E = 1, ρ = 0.5.
Scene make_perpendicular_squares();

// A closed room of tessellated balls: the unit cube seen from inside (its six faces quads, counter-clockwise
// from inside), holding `balls` balls (all spheres³ when 0) in grid order on a spheres × spheres × spheres
// grid, radius 0.3 of the grid's spacing, each cut into `segments` around and segments / 2 rings from pole to
// pole. With one reflectance and emission everywhere it is a furnace,
// B = E / (1 − ρ) on every face, at any size: the check of a transport on many small faces.
struct SphereRoom {
    int spheres = 2;
    std::size_t balls = 0;
    int segments = 8;
    // The bands between the polar caps as two triangles per quad, so every face of a ball is a triangle.
    bool triangles = false;
    // One vertex per corner position within a ball, so each ball is a closed mesh; else every face has its
    // own corners (a polygon soup, with cracks of rounding between faces).
    bool shared_corners = false;
    double reflectance = 0.5;
    double emitted_radiosity = 1.0;  // E; the material's Le is E / π
    std::string source = "sphere room";
};
Scene make_sphere_room(const SphereRoom& room);
// The faces make_sphere_room makes: the room's six and the balls'.
std::size_t sphere_room_faces(const SphereRoom& room);

// builtin:furnace: a sphere room of about `faces` faces (6 wall quads, balls of 224 triangles), ρ = 0.5 and
// E = 1 on every face, so B = E / (1 − ρ) = 2 everywhere. The face count is met to half a ball (112 faces).
inline constexpr double kFurnaceReflectance = 0.5;
inline constexpr double kFurnaceEmission = 1.0;
inline constexpr std::size_t kFurnaceDefaultFaces = 10'000;
inline constexpr std::size_t kFurnaceMinFaces = 1'000;
SphereRoom furnace_room(std::size_t faces);
// Throws InputError naming builtin:furnace-N when `faces` is outside [kFurnaceMinFaces, kMaxSceneFaces].
Scene make_furnace(std::size_t faces);
// The face count N of a built-in name "furnace-N": digits with no leading zero and an optional suffix k
// (thousands) or m (millions), from kFurnaceMinFaces to the scene limit (10m). Throws InputError naming
// builtin:NAME otherwise.
std::size_t furnace_faces(std::string_view name);

}  // namespace rad
