#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <span>
#include <vector>

#include "rad/scene/scene.hpp"

namespace rad {

struct Patch {
    std::uint32_t surface = 0;
    std::uint32_t face = 0;  // the face of the surface's mesh that the patch is part of (for its texture)
    double area = 0.0;
    glm::dvec3 centroid{0.0};
    glm::dvec3 normal{0.0};  // unit, front side
};

// The input face a patch is part of (its surface and its face) as one key, to group patches by face.
inline std::uint64_t face_key(const Patch& p) {
    return (std::uint64_t{p.surface} << 32) | p.face;
}

// The scene cut into patches (quads where possible, else triangles), each no longer than the patch size on
// any edge. Within a surface build_patches makes a conforming mesh: corners are shared and no corner lies
// inside another patch's edge (an ElementTree's leaves may have T-vertices; see `outline`). Surfaces share no
// corners, so colours never bleed from one surface to the next.
struct PatchMesh {
    std::vector<glm::dvec3> points;  // corner positions, double precision, for geometry
    // The same corners in float, as OpenGL draws them. (RayScene makes its own normalized float copy.)
    std::vector<glm::vec3> positions;
    // Corner indices per patch, counter-clockwise from the front. A triangle repeats its last corner
    // (c[3] == c[2]), which is how Embree's quad geometry takes triangles.
    std::vector<glm::uvec4> corners;
    std::vector<Patch> patches;
    // Patches of surface s are [surface_begin[s], surface_begin[s + 1]).
    std::vector<std::uint32_t> surface_begin;
    // Where patches of different sizes meet (adaptive and hierarchical meshes), a corner of the smaller ones
    // can lie inside an edge of the larger one: a T-vertex. Then `outline` lists each patch's whole boundary,
    // its corners and the T-vertices on its edges, counter-clockwise; patch q's are
    // [outline_begin[q], outline_begin[q + 1]). Both are empty for a conforming mesh, whose outlines are the
    // corners.
    std::vector<std::uint32_t> outline_begin;
    std::vector<std::uint32_t> outline;
    // Per surface, 1 where it is back-to-back (Surface::back_to_back); empty where every surface is
    // one-sided.
    std::vector<std::uint8_t> back_to_back;

    std::size_t size() const { return patches.size(); }
    bool is_triangle(std::size_t patch) const { return corners[patch][3] == corners[patch][2]; }
    int corner_count(std::size_t patch) const { return is_triangle(patch) ? 3 : 4; }
    bool is_back_to_back(std::size_t patch) const {
        return !back_to_back.empty() && back_to_back[patches[patch].surface] != 0;
    }
};

// Area, centroid and the given normal of the planar patch with these corners (a triangle repeats c[2]).
Patch measure_patch(std::span<const glm::dvec3> points, const glm::uvec4& corners, std::uint32_t surface,
                    const glm::dvec3& normal);

struct MeshingOptions {
    double patch_size = 0.0;  // largest patch edge in scene units; 0 picks default_patch_size
    std::size_t max_patches = 10'000'000;
};

// A sixteenth of the scene's largest extent, so the default does not depend on the scene's units.
double default_patch_size(const Scene& scene);

// The number of patches build_patches would make, computed without making them.
std::size_t count_patches(const Scene& scene, double patch_size);

// PatchMesh::back_to_back for the scene's surfaces: empty where none is back-to-back.
std::vector<std::uint8_t> back_to_back_surfaces(const Scene& scene);

// Throws SettingError (patch_size, with a size that fits) when the count exceeds max_patches.
PatchMesh build_patches(const Scene& scene, const MeshingOptions& options);

}  // namespace rad
