#pragma once

#include <glm/vec3.hpp>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "rad/scene/texture.hpp"

namespace rad {

// A diffuse material. Reflectance is the albedo ρ per RGB channel, each in [0, 1); emission is the emitted
// radiance Le per channel (MTL `Ke`), so the emitted radiosity is E = π Le. A one-sided material reflects and
// emits on its front only (its back blocks light); a two-sided one (glTF `doubleSided`) on both sides, each
// side with elements of its own. A textured material (OBJ `map_Kd`, glTF `baseColorTexture`) has the image's
// mean as part of its reflectance; the texture's texels vary it over the surface (see albedo_scale), for
// each patch's mean albedo in the transport and per pixel in the display.
struct Material {
    std::string name;
    glm::dvec3 reflectance{0.5};
    glm::dvec3 emission{0.0};
    bool two_sided = false;
    std::shared_ptr<const Texture> texture = nullptr;

    bool emits() const { return emission.x > 0.0 || emission.y > 0.0 || emission.z > 0.0; }
    glm::dvec3 emitted_radiosity() const { return emission * std::numbers::pi; }
};

// The material used where a file names none, or names one that does not exist.
Material default_material();

// Throws InputError, prefixed by `where` (a file and line, say), when reflectance is outside [0, 1) or
// emission is negative, NaN or infinite.
void validate_material(const Material& material, const std::string& where);

// What a reflectance of 1 or more in a file becomes. Real files write white as `Kd 1` (or a colour of 255),
// but a surface that reflects all light makes a closed scene's light grow without end.
inline constexpr double kMaxReflectance = 0.99;

// Counts the materials a loader clamped, for one warning naming the count and the largest value.
class ReflectanceClamps {
  public:
    // Sets every reflectance channel of `material` at or above 1 to kMaxReflectance, counting the material
    // once per name. Values that are negative or not numbers are left for validate_material to refuse.
    void clamp(Material& material);
    // Empty when nothing was clamped.
    std::string warning(const std::string& source) const;

  private:
    std::vector<std::string> names_;
    double largest_ = 0.0;
};

}  // namespace rad
