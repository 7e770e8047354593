#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "rad/scene/builtin_scenes.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

int rings_of(const SphereRoom& room) {
    return std::max(2, room.segments / 2);
}

std::size_t faces_per_ball(const SphereRoom& room) {
    const auto segments = static_cast<std::size_t>(room.segments);
    const auto rings = static_cast<std::size_t>(rings_of(room));
    // Two polar caps of `segments` triangles, and rings − 2 bands of `segments` quads (or twice as many
    // triangles).
    return 2 * segments + (room.triangles ? 2 : 1) * (rings - 2) * segments;
}

std::size_t grid_cells(const SphereRoom& room) {
    const auto side = static_cast<std::size_t>(std::max(room.spheres, 0));
    return side * side * side;
}

std::size_t ball_count(const SphereRoom& room) {
    return room.balls == 0 ? grid_cells(room) : room.balls;
}

void add_polygon(PolygonSoup& soup, std::uint32_t group, std::initializer_list<std::uint32_t> corners) {
    soup.polygons.push_back({std::vector<std::uint32_t>(corners), group});
}

void add_room(PolygonSoup& soup) {
    const auto quad = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
        const auto first = static_cast<std::uint32_t>(soup.positions.size());
        soup.positions.insert(soup.positions.end(), {a, b, c, d});
        add_polygon(soup, 0, {first, first + 1, first + 2, first + 3});
    };
    // The room [0, 1]³, each face counter-clockwise seen from inside.
    quad({0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1});
    quad({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0});
    quad({0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1});
    quad({1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0});
    quad({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
    quad({0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1});
}

void add_ball(PolygonSoup& soup, const SphereRoom& room, glm::dvec3 centre, double radius) {
    const int rings = rings_of(room), segments = room.segments;
    const auto position = [&](int ring, int a) {
        const double theta = std::numbers::pi * ring / rings;
        const double phi = 2.0 * std::numbers::pi * a / segments;
        return centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                            std::sin(theta) * std::sin(phi));
    };
    // Shared: the north pole, rings − 1 circles of `segments`, the south pole, once each.
    const auto first = static_cast<std::uint32_t>(soup.positions.size());
    if (room.shared_corners) {
        for (int ring = 0; ring <= rings; ++ring) {
            const int around = ring == 0 || ring == rings ? 1 : segments;
            for (int a = 0; a < around; ++a) soup.positions.push_back(position(ring, a));
        }
    }
    // Else each face gets its own corners, made where they are asked for.
    const auto at = [&](int ring, int a) -> std::uint32_t {
        if (!room.shared_corners) {
            soup.positions.push_back(position(ring, a));
            return static_cast<std::uint32_t>(soup.positions.size() - 1);
        }
        if (ring == 0) return first;
        if (ring == rings) return first + 1 + static_cast<std::uint32_t>((rings - 1) * segments);
        return first + 1 + static_cast<std::uint32_t>((ring - 1) * segments + a % segments);
    };
    // Counter-clockwise seen from outside the ball.
    for (int r = 0; r < rings; ++r) {
        for (int a = 0; a < segments; ++a) {
            if (r == 0) {
                add_polygon(soup, 1, {at(0, a), at(1, a + 1), at(1, a)});
            } else if (r == rings - 1) {
                add_polygon(soup, 1, {at(r, a), at(r, a + 1), at(r + 1, a)});
            } else if (room.triangles) {
                add_polygon(soup, 1, {at(r, a), at(r, a + 1), at(r + 1, a + 1)});
                add_polygon(soup, 1, {at(r, a), at(r + 1, a + 1), at(r + 1, a)});
            } else {
                add_polygon(soup, 1, {at(r, a), at(r, a + 1), at(r + 1, a + 1), at(r + 1, a)});
            }
        }
    }
}

}  // namespace

std::size_t sphere_room_faces(const SphereRoom& room) {
    return 6 + ball_count(room) * faces_per_ball(room);
}

Scene make_sphere_room(const SphereRoom& room) {
    if (room.spheres < 1 || room.segments < 3 || room.balls > grid_cells(room))
        throw InputError(room.source +
                         ": a sphere room needs at least one ball per side, 3 segments, and "
                         "no more balls than grid cells");
    PolygonSoup soup;
    soup.source = room.source;
    Material material;
    material.name = "furnace";
    material.reflectance = glm::dvec3(room.reflectance);
    material.emission = glm::dvec3(room.emitted_radiosity / std::numbers::pi);
    soup.groups.push_back({"room", material});
    soup.groups.push_back({"balls", material});
    const std::size_t balls = ball_count(room);
    soup.polygons.reserve(sphere_room_faces(room));
    add_room(soup);
    const double spacing = 1.0 / room.spheres, radius = 0.3 * spacing;
    std::size_t placed = 0;
    for (int i = 0; i < room.spheres && placed < balls; ++i)
        for (int j = 0; j < room.spheres && placed < balls; ++j)
            for (int k = 0; k < room.spheres && placed < balls; ++k, ++placed)
                add_ball(soup, room, spacing * glm::dvec3(i + 0.5, j + 0.5, k + 0.5), radius);
    Scene scene = build_scene(soup);
    // Above the floor's middle, below every ball (the lowest reach 0.2 spacings up), looking up.
    scene.camera = Camera{{0.5, 0.1 * spacing, 0.5}, {0.5, 1.0, 0.5}, {0, 0, 1}, 90.0};
    return scene;
}

}  // namespace rad
