#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

// Which display patches show texel detail, and their texture coordinates: a patch is textured where its
// surface has a texture and its face has coordinates. Built once per display mesh.
class PatchTexturing {
  public:
    // No patch is textured when `texturing.scene` is null.
    PatchTexturing(const PatchMesh& mesh, const DisplayTexturing& texturing);

    bool any() const { return any_; }
    bool textured(std::size_t patch) const { return !textured_.empty() && textured_[patch] != 0; }
    // The texture coordinates of a textured patch at `point`; (0, 0) for any other patch.
    glm::vec2 texcoord(std::size_t patch, const glm::dvec3& point) const;

    // The display's textured ranges (runs of textured triangles of one surface), which patches are textured
    // and what vertex_radiance needs per patch (light_textured_patches); the triangles and patch_surface
    // must be final.
    void finish(DisplayMesh& display) const;

  private:
    const PatchMesh& mesh_;
    DisplayTexturing texturing_;
    std::vector<std::uint8_t> textured_;
    bool any_ = false;
};

// The light's part of texel detail, from `scene`'s materials and each display patch's reflectance: the
// textured ranges' albedo scale and emitted radiance, and DisplayLight::patch_irradiance. Throws
// std::invalid_argument when the reflectance does not have one entry per display patch.
void light_textured_patches(DisplayMesh& display, const Scene& scene,
                            std::span<const glm::dvec3> reflectance);

}  // namespace rad
