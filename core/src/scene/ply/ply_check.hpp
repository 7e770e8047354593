#pragma once

#include <string>

#include "scene/scene_limits.hpp"

namespace rad {

// OpenMesh's PLY reader trusts its input: a forged count makes it allocate without bound and a malformed
// number can make it write out of bounds. This walks the header and every element first (ASCII or binary)
// and throws InputError naming the file and line (or element) at the first thing that is wrong: counts the
// file cannot hold, malformed or non-finite numbers, face indices out of range, truncation, extra data.
// Vertex and face counts beyond `limits` are refused from the header alone.
void check_ply(const std::string& path, const std::string& bytes, const SceneFileLimits& limits = {});

}  // namespace rad
