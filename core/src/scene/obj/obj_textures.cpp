#include "scene/obj/obj_textures.hpp"

#include <filesystem>
#include <optional>
#include <utility>

#include "rad/util/error.hpp"
#include "scene/scene_folder.hpp"
#include "scene/text_file.hpp"
#include "scene/texture_mean.hpp"

namespace rad {

ObjTextures::ObjTextures(std::string obj_path) : obj_path_(std::move(obj_path)) {}

void ObjTextures::apply(const std::string& texture, Material& material) {
    if (texture.empty()) return;
    std::string why;
    const std::filesystem::path path =
        file_in_scene_folder(std::filesystem::path(obj_path_).parent_path(), texture, why);
    std::optional<glm::dvec3> mean;
    if (!path.empty()) {
        try {
            const std::string bytes = read_text_file(path.string());
            mean =
                mean_linear_colour(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), why);
        } catch (const InputError&) {
            why = "cannot be read";
        }
    } else if (why.empty()) {
        why = "not found";
    }
    if (mean) {
        material.reflectance *= *mean;
        return;
    }
    if (unread_++ == 0) first_unread_ = quote_for_message(texture) + " (" + why + ")";
}

std::string ObjTextures::warning() const {
    if (unread_ == 0) return {};
    return obj_path_ + ": " + std::to_string(unread_) + " texture(s) (map_Kd) not read, first " +
           first_unread_ + "; those materials keep their Kd";
}

}  // namespace rad
