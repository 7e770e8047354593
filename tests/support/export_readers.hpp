#pragma once

#include <tiny_gltf.h>

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace rad::test {

// A scene export read back by the libraries other programs use: OpenMesh for PLY, tinygltf for glTF.
struct ExportedMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::uvec3> triangles;
    std::vector<std::array<std::uint8_t, 3>> colour_bytes;  // PLY: red green blue
    std::vector<glm::vec3> colours;                         // glTF: COLOR_0
    std::vector<glm::vec3> radiance;                        // PLY: radiance_r/g/b; glTF: _RADIANCE
};

// Throws std::runtime_error saying what is missing or malformed.
ExportedMesh read_ply_export(const std::string& path);
// .gltf or .glb by the extension: one mesh whose primitives share their vertices, triangles in primitive
// order; `model` (if given) receives the whole document.
ExportedMesh read_gltf_export(const std::string& path, tinygltf::Model* model = nullptr);

}  // namespace rad::test
