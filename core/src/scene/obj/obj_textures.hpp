#pragma once

#include <string>
#include <vector>

#include "rad/scene/material.hpp"

namespace rad {

// MTL `map_Kd`: the transport sees each material's mean albedo, so a textured material's reflectance is Kd
// times the texture's mean linear colour. A texture that is missing, refused by the scene-folder rule or
// not decodable leaves Kd alone; such textures are counted in one warning.
class ObjTextures {
  public:
    explicit ObjTextures(std::string obj_path);

    // Multiplies `material`'s reflectance by the mean of `texture` (a name from the MTL, relative to the
    // OBJ's folder); nothing when `texture` is empty.
    void apply(const std::string& texture, Material& material);
    // Empty when every texture was read.
    std::string warning() const;

  private:
    std::string obj_path_;
    std::size_t unread_ = 0;
    std::string first_unread_;  // "'name' (why)"
};

}  // namespace rad
