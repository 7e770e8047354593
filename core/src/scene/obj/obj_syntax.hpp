#pragma once

#include <cstddef>
#include <cstdint>
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
    // The corners of each face of 3 or more, in the file's order: tinyobjloader keeps a face's count in a
    // byte, so a face of 256 corners would read as 0.
    std::vector<std::uint32_t> face_corners;
    std::size_t short_faces = 0;  // of fewer than 3 corners, which tinyobjloader skips
};

ObjFacts check_obj_text(std::string_view text, const std::string& path, const SceneFileLimits& limits = {});

// Material name -> line of its `newmtl`. Checks Kd and Ke: three finite numbers >= 0 each.
std::map<std::string, std::size_t> check_mtl_text(std::string_view text, const std::string& path);

}  // namespace rad
