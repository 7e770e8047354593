#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/display/patch_restriction.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// A hierarchy's leaves are many, of every size (the finest where a link asked for them, a thousandth of the
// scene beside a corner) and hold light linked to larger elements; drawn as they are, every one of their
// vertices is traced and gathered. The display draws such a solution on patches of its own instead: the
// scene meshed at `patch_size` (build_patches), each taking the mean of the leaves under it, weighted by
// their exposed shares so a patch beside a block shows the light of its exposed part.
struct DisplayPatches {
    PatchMesh mesh;
    PatchRestriction from_solution;
    std::vector<double>
        exposed;  // per display patch, the share of its area not covered (the leaves' under it)
};

// Samples per display patch, on a regular grid of its area: which leaf holds each is found by a short ray
// into the surface, so any two meshes of the same scene can be matched.
inline constexpr int kDisplayPatchSamples = 16;

// `solution_rays` are over `solution`; `exposed` gives each solution patch's uncovered share of its area (1
// where nothing covers it). Throws std::invalid_argument when `exposed` has another count, SettingError as
// build_patches does.
DisplayPatches make_display_patches(const Scene& scene, const PatchMesh& solution,
                                    const RayScene& solution_rays, std::span<const double> exposed,
                                    double patch_size);

}  // namespace rad
