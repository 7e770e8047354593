#pragma once

#include <cstddef>
#include <string>

#include "scene/scene_limits.hpp"

namespace rad {

// OpenMesh's PLY reader trusts its input: a forged count makes it allocate without bound and a malformed
// number can make it write out of bounds. This walks the header and every element first (ASCII or binary)
// and throws InputError naming the file and line (or element) at the first thing that is wrong: counts the
// file cannot hold, malformed or non-finite numbers, face indices out of range, truncation, extra data.
// Vertex and face counts beyond `limits` are refused from the header alone.
//
// Faces of fewer than 3 corners or with a corner repeated, which OpenMesh cannot add (it would store their
// colour out of bounds), are counted, and `repaired` holds the file's bytes without them (the header's face
// count lowered) for OpenMesh to read instead; it is empty when there are none.
struct PlyCheck {
    std::size_t skipped_faces = 0;
    std::string repaired;
};
PlyCheck check_ply(const std::string& path, const std::string& bytes, const SceneFileLimits& limits = {});

}  // namespace rad
