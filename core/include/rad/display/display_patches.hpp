#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// How the patches a display is drawn on take their values from a solution on other patches of the same
// surfaces: display patch d's value is Σ share[k] · value[source[k]] for k in [begin[d], begin[d + 1]), the
// shares summing to 1. Empty: the display is drawn on the solution's own patches.
struct PatchRestriction {
    std::vector<std::uint32_t> begin;
    std::vector<std::uint32_t> source;
    std::vector<float> share;
    std::size_t source_count = 0;  // the solution's patches

    bool empty() const { return begin.empty(); }
    std::size_t size() const { return begin.empty() ? 0 : begin.size() - 1; }
    // Per display patch, from one value per solution patch. Throws std::invalid_argument for another count.
    std::vector<glm::dvec3> apply(std::span<const glm::dvec3> values) const;
};

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
