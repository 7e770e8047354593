#pragma once

// The leak suite: closed rooms built the ways modelling tools and IFC exporters build them
// (assets/hard/leak_*.obj, written by scripts/leak_rooms.py), lit from outside or from a neighbouring room,
// and how much of that light reaches their closed interior, which must stay dark.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <string>

#include "rad/io/image.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

struct LeakRoom {
    std::string name;      // the file's stem in assets/hard
    std::string models;    // what the room is built of, in a few words
    bool sky = true;       // lit by a uniform sky of radiance 1 from outside; else by its own lamp next door
    BoundingBox interior;  // the closed volume no light may enter
};

// The suite's rooms, in the order scripts/leak_rooms.py writes them.
std::span<const LeakRoom> leak_rooms();

// The light in the interior against the light outside.
struct Leak {
    // The largest radiosity (any channel) of an element looking into the interior.
    double worst_inside = 0.0;
    // The area-weighted mean luminance radiosity of the lit elements that emit nothing.
    double lit_mean = 0.0;
    std::size_t inside = 0;  // the elements looking into the interior
    double ratio() const { return lit_mean > 0.0 ? worst_inside / lit_mean : 0.0; }
};

// Whether the patch lies on the interior's boundary with its front looking in.
bool looks_into(const Patch& patch, const BoundingBox& interior);

// Over the elements of a solution (`elements`, one radiosity each).
Leak measure_leak(const Scene& scene, const PatchMesh& elements, std::span<const glm::dvec3> radiosity,
                  const BoundingBox& interior);

// A view from the interior's centre towards the corner at its lowest coordinates: the floor and the two walls
// that meet there, where light crossing a wall or a floor's joint would show.
Camera interior_camera(const BoundingBox& interior);

// The same in an image of radiance from interior_camera: the brightest pixel's radiance × π (the radiosity of
// a diffuse surface that shows it) against `lit_mean`.
double image_leak(const Image& radiance, double lit_mean);

}  // namespace rad
