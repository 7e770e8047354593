#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_limits.hpp"

namespace rad {

// tinyobjloader reads a malformed number as 0 and an out-of-range index as a warning, without a line
// number. These checks run first, so every such mistake is reported as FILE:LINE: what is wrong.

struct ObjLibrary {
    std::string name;  // as written after mtllib
    std::size_t line = 0;
};

struct ObjFacts {
    std::vector<ObjLibrary> libraries;
    std::size_t vertex_count = 0;
    std::size_t face_count = 0;
};

ObjFacts check_obj_text(std::string_view text, const std::string& path, const SceneFileLimits& limits = {});

// Material name -> line of its `newmtl`. Checks Kd (three numbers in [0, 1)) and Ke (three numbers >= 0).
std::map<std::string, std::size_t> check_mtl_text(std::string_view text, const std::string& path);

}  // namespace rad
