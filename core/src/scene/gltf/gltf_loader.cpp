#include "rad/scene/polygon_soup.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"
#include "scene/gltf/gltf_camera.hpp"
#include "scene/gltf/gltf_file.hpp"
#include "scene/gltf/gltf_lights.hpp"
#include "scene/gltf/gltf_materials.hpp"
#include "scene/gltf/gltf_meshes.hpp"
#include "scene/gltf/gltf_nodes.hpp"

namespace rad {

namespace {

// The extensions we read; a file that requires another cannot be shown as its author meant.
void check_required_extensions(const GltfFile& file) {
    for (const std::string& ext : file.model.extensionsRequired) {
        if (ext == "KHR_lights_punctual" || ext == "KHR_materials_emissive_strength" ||
            ext == "KHR_texture_transform" || ext == "KHR_materials_unlit")
            continue;
        throw InputError(
            gltf_message(file, "requires extension '" + gltf_name(ext, "") + "', which is not supported"));
    }
}

}  // namespace

Scene load_gltf(const std::string& path) {
    GltfFile file = read_gltf(path);
    check_required_extensions(file);
    ReflectanceClamps clamps;
    const std::vector<Material> materials = convert_materials(file, clamps);
    if (const std::string w = clamps.warning(path); !w.empty()) file.warnings.push_back(w);
    const std::vector<PlacedNode> nodes = place_nodes(file);

    PolygonSoup soup;
    soup.source = path;
    add_meshes(file, nodes, materials, soup);
    Sun sun;
    add_lights(file, nodes, soup, sun);
    std::optional<Camera> camera = first_camera(file, nodes);

    Scene scene = build_scene(soup);
    scene.camera = camera;
    scene.sun = sun;
    if (sun.present()) std::erase(scene.warnings, no_emitter_warning(scene.source));
    scene.warnings.insert(scene.warnings.begin(), file.warnings.begin(), file.warnings.end());
    return scene;
}

}  // namespace rad
