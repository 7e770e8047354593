#include "scene/obj/obj_textures.hpp"

#include <filesystem>
#include <utility>

#include "rad/util/error.hpp"
#include "scene/scene_folder.hpp"
#include "scene/text_file.hpp"
#include "scene/texture_image.hpp"

namespace rad {

ObjTextures::ObjTextures(std::string obj_path) : obj_path_(std::move(obj_path)) {}

void ObjTextures::apply(const std::string& texture, Material& material) {
    if (texture.empty()) return;
    std::string why;
    const std::filesystem::path path =
        file_in_scene_folder(std::filesystem::path(obj_path_).parent_path(), texture, why);
    std::shared_ptr<const Texture> image;
    if (const auto it = decoded_.find(path.string()); !path.empty() && it != decoded_.end()) {
        image = it->second;
    } else if (!path.empty()) {
        try {
            const std::string bytes = read_text_file(path.string());
            image = decode_texture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(),
                                   texture, why);
        } catch (const InputError&) {
            why = "cannot be read";
        }
        if (image) decoded_.emplace(path.string(), image);
    } else if (why.empty()) {
        why = "not found";
    }
    if (image) {
        material.reflectance *= image->mean;
        material.texture = image;
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
