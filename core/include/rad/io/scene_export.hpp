#pragma once

#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>
#include <span>

#include "rad/display/display_mesh.hpp"

namespace rad {

// The solved scene as other programs open it: the display mesh the viewer draws (positions, normals,
// triangles) with each vertex's colour.
//   .ply  binary little endian (OpenMesh): x y z, nx ny nz, red green blue as 8-bit sRGB of the displayed
//         value (what a PNG pixel of that radiance holds, so MeshLab and Blender show what the viewer
//         shows), and radiance_r radiance_g radiance_b, the linear radiance L as floats.
//   .gltf glTF 2.0 with its buffer embedded (base64), one file; .glb the same as binary glTF. One mesh, one
//         node: POSITION (with min and max), NORMAL, uint32 indices, COLOR_0 the displayed value (linear
//         float, as glTF wants), _RADIANCE the linear radiance L, and an unlit material
//         (KHR_materials_unlit) so viewers show the colours as they are.
// The displayed value is L · 2^exposure clamped to [0, 1], as a PNG image is written.
enum class ExportFormat { ply, gltf, glb };

// The format a file name asks for by its extension, in any case; nothing for any other extension.
std::optional<ExportFormat> export_format(const std::filesystem::path& path);

struct ExportOptions {
    double exposure = 0.0;  // EV: the displayed value is L · 2^exposure
};

// The displayed value of radiance L, L · 2^exposure clamped to [0, 1] (linear); float arithmetic as the PNG
// writer does it, so the two agree to the bit.
glm::vec3 displayed_value(const glm::vec3& radiance, double exposure);

// Writes the mesh with radiance L per vertex (`radiance` holds mesh.vertex_count() values) in the format of
// path's extension, through a temporary file renamed into place, so the file appears whole or not at all.
// Throws InputError for an unknown extension, std::invalid_argument for an empty or inconsistent mesh, a
// non-finite position or radiance, or an exposure whose scale 2^exposure is not a finite positive float
// (nothing is written then), and std::runtime_error when writing fails.
void export_scene(const std::filesystem::path& path, const DisplayMesh& mesh,
                  std::span<const glm::vec3> radiance, const ExportOptions& options = {});

// The writers behind export_scene, which has checked their input: each writes `path` directly.
void write_ply_export(const std::filesystem::path& path, const DisplayMesh& mesh,
                      std::span<const glm::vec3> radiance, const ExportOptions& options);
void write_gltf_export(const std::filesystem::path& path, const DisplayMesh& mesh,
                       std::span<const glm::vec3> radiance, const ExportOptions& options, bool binary);

}  // namespace rad
