#pragma once

#include <string>

namespace rad {

// The extension of a path, dot included, in lower case: "scene.OBJ" gives ".obj".
std::string lowercase_extension(const std::string& path);

}  // namespace rad
