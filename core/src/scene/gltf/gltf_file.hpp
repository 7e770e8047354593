#pragma once

#include <tiny_gltf.h>

#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "rad/scene/texture.hpp"

namespace rad {

// A glTF file as tinygltf read it, with what was learnt on the way.
struct GltfFile {
    std::string path;  // for messages
    tinygltf::Model model;
    // Per image index, the images that could be decoded.
    std::map<int, std::shared_ptr<const Texture>> images;
    std::vector<std::string> warnings;
};

// Reads a .gltf (its buffers and images external, in the file's folder, or data: URIs) or a .glb, chosen by
// the file's first bytes. Throws InputError naming the file for anything tinygltf or our checks refuse.
GltfFile read_gltf(const std::string& path);

// A name from the file as the scene uses it: `fallback` when empty, control characters (a newline would
// break a one-line message) replaced by '?'.
std::string gltf_name(const std::string& name, const std::string& fallback);

// "path: what" as one line, for every message about this file.
std::string gltf_message(const GltfFile& file, const std::string& what);

}  // namespace rad
