#include "scene/gltf/gltf_materials.hpp"

#include <cmath>
#include <memory>

#include "rad/util/error.hpp"

namespace rad {

namespace {

// The image of texture `texture`, or null (with a warning) when it names no image that decoded.
std::shared_ptr<const Texture> texture_image(GltfFile& file, int texture, const std::string& where) {
    if (texture < 0) return nullptr;
    const auto& textures = file.model.textures;
    std::string why;
    if (static_cast<std::size_t>(texture) >= textures.size()) {
        why = "texture " + std::to_string(texture) + " does not exist";
    } else {
        const int image = textures[static_cast<std::size_t>(texture)].source;
        const auto found = file.images.find(image);
        if (found != file.images.end()) return found->second;
        why = image < 0 ? "texture " + std::to_string(texture) + " has no image stb_image can decode"
                        : "image " + std::to_string(image) + " could not be decoded";
    }
    file.warnings.push_back(gltf_message(file, where + ": " + why + "; the factor alone is used"));
    return nullptr;
}

glm::dvec3 rgb(const std::vector<double>& values, glm::dvec3 otherwise) {
    return values.size() >= 3 ? glm::dvec3(values[0], values[1], values[2]) : otherwise;
}

double emissive_strength(const tinygltf::Material& m) {
    const auto ext = m.extensions.find("KHR_materials_emissive_strength");
    if (ext == m.extensions.end() || !ext->second.Has("emissiveStrength")) return 1.0;
    const tinygltf::Value& strength = ext->second.Get("emissiveStrength");
    // A strength that is not a number is refused by validate_material as a NaN emission.
    return strength.IsNumber() ? strength.GetNumberAsDouble() : std::nan("");
}

Material convert(GltfFile& file, std::size_t index, ReflectanceClamps& clamps) {
    const tinygltf::Material& m = file.model.materials[index];
    const std::string where = "materials[" + std::to_string(index) + "]";
    Material material;
    material.name = gltf_name(m.name, "material " + std::to_string(index));
    material.two_sided = m.doubleSided;
    const auto& pbr = m.pbrMetallicRoughness;
    material.reflectance = rgb(pbr.baseColorFactor, glm::dvec3(1.0));
    material.texture = texture_image(file, pbr.baseColorTexture.index, where + " base colour texture");
    if (material.texture) material.reflectance *= material.texture->mean;
    // The emission is uniform over the surface: the emissive texture's mean.
    material.emission = rgb(m.emissiveFactor, glm::dvec3(0.0)) * emissive_strength(m);
    if (m.emissiveTexture.index >= 0) {
        if (const auto image = texture_image(file, m.emissiveTexture.index, where + " emissive texture"))
            material.emission *= image->mean;
    }
    clamps.clamp(material);
    validate_material(material, gltf_message(file, where));
    return material;
}

}  // namespace

std::vector<Material> convert_materials(GltfFile& file, ReflectanceClamps& clamps) {
    std::vector<Material> materials;
    for (std::size_t i = 0; i < file.model.materials.size(); ++i)
        materials.push_back(convert(file, i, clamps));
    return materials;
}

}  // namespace rad
