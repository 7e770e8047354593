#pragma once

#include <vector>

#include "rad/scene/material.hpp"
#include "scene/gltf/gltf_file.hpp"

namespace rad {

// The file's materials, in its order. Reflectance is baseColorFactor's RGB times the linear mean of the base
// colour texture; emission (Le) is emissiveFactor times the mean of the emissive texture times
// KHR_materials_emissive_strength; doubleSided makes the material two-sided. A texture that cannot be used
// is a warning (the factor alone is kept); a reflectance of 1 or more is clamped through `clamps`; a value
// that is negative or not finite is refused naming materials[N].
std::vector<Material> convert_materials(GltfFile& file, ReflectanceClamps& clamps);

}  // namespace rad
