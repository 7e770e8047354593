#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "rad/scene/material.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// What a loader reads from a file before it becomes a Scene: positions, polygons as index lists, and
// groups (one per future surface), each with its material. Loaders validate syntax, indices and values;
// build_scene turns the soup into surfaces.
struct PolygonSoup {
    struct Polygon {
        std::vector<std::uint32_t> vertices;
        std::uint32_t group = 0;
        // One per vertex, into texcoords; empty where the polygon has none.
        std::vector<std::uint32_t> texcoords = {};
    };
    struct Group {
        std::string name;
        Material material;
    };

    std::string source;
    std::vector<glm::dvec3> positions;
    // Texture coordinates in glTF's convention (v = 0 at the image's top row).
    std::vector<glm::dvec2> texcoords;
    std::vector<Polygon> polygons;
    std::vector<Group> groups;
};

// Surfaces from the groups' faces. Zero-area polygons and repeats of an earlier polygon (the same corners in
// the same cyclic order, from any corner, in any group) are dropped, each kind counted in a warning; faces
// that reach into a closed solid are cut where they enter it and the parts inside dropped, with a warning
// (core/src/scene/solid_cuts.hpp); polygons that are not planar and convex are
// triangulated; an edge that OpenMesh cannot take (non-manifold) gets its own copy of the vertices. Two-sided
// faces go to back-to-back surfaces of their own (Surface::back_to_back): pairs of polygons with the same
// corners in opposite orders (counted in a warning), and the faces of a two-sided material, with a reversed
// copy as the back (a surface named "NAME (back)"). A group's one-sided faces stay in one surface. Of two
// polygons of different surfaces that lie in one plane, face the same way and overlap, the emitter's (else
// the smaller surface's) is moved a thousandth of the scene's diagonal in front of the other, with a warning
// (core/src/scene/coplanar_faces.hpp).
// Throws InputError when nothing with area is left.
Scene build_scene(const PolygonSoup& soup);

}  // namespace rad
