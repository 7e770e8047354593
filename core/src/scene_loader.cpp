#include "rad/scene_loader.hpp"

#include <algorithm>
#include <filesystem>

#include "rad/builtin_scenes.hpp"
#include "rad/error.hpp"

namespace rad {

namespace {

std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

}  // namespace

Scene load_scene(const std::string& spec) {
    constexpr std::string_view kBuiltin = "builtin:";
    if (spec.starts_with(kBuiltin)) return make_builtin_scene(spec.substr(kBuiltin.size()));
    const std::string ext = lower_extension(spec);
    if (ext == ".obj") return load_obj(spec);
    if (ext == ".ply") return load_ply(spec);
    throw InputError(spec + ": unknown scene format '" + ext + "' (use .obj, .ply or builtin:NAME)");
}

}  // namespace rad
