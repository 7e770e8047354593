#include "rad/scene/scene_loader.hpp"

#include "rad/scene/builtin_scenes.hpp"
#include "rad/util/error.hpp"
#include "rad/util/file_names.hpp"

namespace rad {

Scene load_scene(const std::string& spec) {
    constexpr std::string_view kBuiltin = "builtin:";
    if (spec.starts_with(kBuiltin)) return make_builtin_scene(spec.substr(kBuiltin.size()));
    const std::string ext = lowercase_extension(spec);
    if (ext == ".obj") return load_obj(spec);
    if (ext == ".ply") return load_ply(spec);
    if (ext == ".gltf" || ext == ".glb") return load_gltf(spec);
    throw InputError(spec + ": unknown scene format '" + ext +
                     "' (use .obj, .ply, .gltf, .glb or builtin:NAME)");
}

}  // namespace rad
