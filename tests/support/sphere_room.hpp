#pragma once

// A closed room of tessellated spheres: a cube seen from inside, holding spheres x spheres x spheres balls
// on a grid, each cut into `segments` around and segments / 2 from pole to pole (2 segments² triangles and
// quads a ball). With one reflectance and one emission everywhere it is a furnace, B = E / (1 − ρ) on every
// face, at any size: the check of a transport on many small faces.

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <numbers>
#include <string>

#include "rad/scene/material.hpp"
#include "rad/scene/polygon_soup.hpp"

namespace rad::test {

inline Scene sphere_room(int spheres, int segments, double reflectance, double emitted_radiosity) {
    PolygonSoup soup;
    soup.source = "sphere room";
    Material material;
    material.name = "furnace";
    material.reflectance = glm::dvec3(reflectance);
    material.emission = glm::dvec3(emitted_radiosity / std::numbers::pi);
    soup.groups.push_back({"room", material});
    soup.groups.push_back({"balls", material});
    auto add = [&](std::initializer_list<glm::dvec3> corners, std::uint32_t group) {
        PolygonSoup::Polygon polygon;
        polygon.group = group;
        for (const glm::dvec3& c : corners) {
            polygon.vertices.push_back(static_cast<std::uint32_t>(soup.positions.size()));
            soup.positions.push_back(c);
        }
        soup.polygons.push_back(polygon);
    };
    // The room [0, 1]³, each face counter-clockwise seen from inside.
    add({{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}, 0);
    add({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, 0);
    add({{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, 0);
    add({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}, 0);
    add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 0);
    add({{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}, 0);
    const double spacing = 1.0 / spheres, radius = 0.3 * spacing;
    const int rings = std::max(2, segments / 2);
    for (int i = 0; i < spheres; ++i)
        for (int j = 0; j < spheres; ++j)
            for (int k = 0; k < spheres; ++k) {
                const glm::dvec3 centre((i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing);
                auto at = [&](int ring, int around) {
                    const double theta = std::numbers::pi * ring / rings;
                    const double phi = 2.0 * std::numbers::pi * around / segments;
                    return centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                        std::sin(theta) * std::sin(phi));
                };
                // Counter-clockwise seen from outside the ball.
                for (int r = 0; r < rings; ++r)
                    for (int a = 0; a < segments; ++a) {
                        if (r == 0) {
                            add({at(0, a), at(1, a + 1), at(1, a)}, 1);
                        } else if (r == rings - 1) {
                            add({at(r, a), at(r, a + 1), at(r + 1, a)}, 1);
                        } else {
                            add({at(r, a), at(r, a + 1), at(r + 1, a + 1), at(r + 1, a)}, 1);
                        }
                    }
            }
    return build_scene(soup);
}

}  // namespace rad::test
