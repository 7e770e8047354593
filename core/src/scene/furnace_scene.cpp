#include <algorithm>
#include <cmath>

#include "furnace_name.hpp"
#include "rad/scene/builtin_scenes.hpp"

namespace rad {

SphereRoom furnace_room(std::size_t faces) {
    SphereRoom room;
    // Balls of 16 segments and 8 rings, all triangles: 224 faces each, fine enough to look round and coarse
    // enough that a large furnace is many objects, which is what clustering is for.
    room.segments = 16;
    room.triangles = true;
    room.shared_corners = true;  // closed balls, as a real mesh of a million triangles is
    room.reflectance = kFurnaceReflectance;
    room.emitted_radiosity = kFurnaceEmission;
    room.spheres = 1;
    room.balls = 1;
    const std::size_t per_ball = sphere_room_faces(room) - 6;
    room.balls = std::max<std::size_t>(
        1, static_cast<std::size_t>(
               std::llround(static_cast<double>(faces > 6 ? faces - 6 : 0) / static_cast<double>(per_ball))));
    while (static_cast<std::size_t>(room.spheres) * room.spheres * room.spheres < room.balls) ++room.spheres;
    room.source =
        faces == kFurnaceDefaultFaces ? "builtin:furnace" : "builtin:furnace-" + std::to_string(faces);
    return room;
}

Scene make_furnace(std::size_t faces) {
    check_furnace_faces(faces, "builtin:furnace-" + std::to_string(faces));
    return make_sphere_room(furnace_room(faces));
}

}  // namespace rad
