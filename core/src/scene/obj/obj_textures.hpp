#pragma once

#include <map>
#include <memory>
#include <string>

#include "rad/scene/material.hpp"

namespace rad {

// MTL `map_Kd`: a textured material's reflectance is Kd times the texture's mean linear colour, and the
// material keeps the texture (each image decoded once, however many materials use it). A texture that is
// missing, refused by the scene-folder rule or not decodable leaves Kd alone; such textures are counted in
// one warning.
class ObjTextures {
  public:
    explicit ObjTextures(std::string obj_path);

    // Gives `material` the image `texture` (a name from the MTL, relative to the OBJ's folder) and
    // multiplies its reflectance by the image's mean; nothing when `texture` is empty.
    void apply(const std::string& texture, Material& material);
    // Empty when every texture was read.
    std::string warning() const;

  private:
    std::string obj_path_;
    std::size_t unread_ = 0;
    std::string first_unread_;                                       // "'name' (why)"
    std::map<std::string, std::shared_ptr<const Texture>> decoded_;  // by path
};

}  // namespace rad
