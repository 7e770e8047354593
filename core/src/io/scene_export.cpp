#include "rad/io/scene_export.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <stdexcept>
#include <string>

#include "rad/io/atomic_file.hpp"
#include "rad/util/error.hpp"
#include "rad/util/file_names.hpp"

namespace rad {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string describe(const glm::vec3& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

float exposure_scale(double exposure) {
    return static_cast<float>(std::exp2(exposure));
}

// Everything a writer relies on, checked before any file is opened, so bad values never reach a file.
void check_export_input(const std::filesystem::path& path, const DisplayMesh& mesh,
                        std::span<const glm::vec3> radiance, const ExportOptions& options) {
    const std::string what = "cannot export " + path.string() + ": ";
    if (mesh.triangles.empty()) throw std::invalid_argument(what + "the mesh has no triangles");
    if (radiance.size() != mesh.vertex_count() || mesh.normals.size() != mesh.vertex_count()) {
        throw std::invalid_argument(what + "radiance or normals do not match the " +
                                    std::to_string(mesh.vertex_count()) + " vertices");
    }
    const float scale = exposure_scale(options.exposure);
    if (!std::isfinite(scale) || !(scale > 0.0f)) {
        throw std::invalid_argument(what + "exposure " + std::to_string(options.exposure) +
                                    " is out of range");
    }
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        if (!finite(mesh.positions[v]) || !finite(mesh.normals[v])) {
            throw std::invalid_argument(what + "vertex " + std::to_string(v) + " has a non-finite position " +
                                        describe(mesh.positions[v]) + " or normal");
        }
        if (!finite(radiance[v])) {
            throw std::invalid_argument(what + "vertex " + std::to_string(v) + " has a non-finite radiance " +
                                        describe(radiance[v]));
        }
    }
    for (const glm::uvec3& t : mesh.triangles) {
        if (std::max({t.x, t.y, t.z}) >= mesh.vertex_count()) {
            throw std::invalid_argument(what + "a triangle refers to a vertex that does not exist");
        }
    }
}

}  // namespace

std::optional<ExportFormat> export_format(const std::filesystem::path& path) {
    const std::string ext = lowercase_extension(path.string());
    if (ext == ".ply") return ExportFormat::ply;
    if (ext == ".gltf") return ExportFormat::gltf;
    if (ext == ".glb") return ExportFormat::glb;
    return std::nullopt;
}

glm::vec3 displayed_value(const glm::vec3& radiance, double exposure) {
    return glm::clamp(radiance * exposure_scale(exposure), 0.0f, 1.0f);
}

void export_scene(const std::filesystem::path& path, const DisplayMesh& mesh,
                  std::span<const glm::vec3> radiance, const ExportOptions& options) {
    const std::optional<ExportFormat> format = export_format(path);
    if (!format) {
        throw InputError(path.string() + ": unknown export format '" + lowercase_extension(path.string()) +
                         "' (use .ply, .gltf or .glb)");
    }
    check_export_input(path, mesh, radiance, options);
    replace_file_atomically(path, [&](const std::filesystem::path& temporary) {
        // One colour per vertex: a textured vertex takes the texel under it.
        if (*format == ExportFormat::ply)
            write_ply_export(temporary, mesh, vertex_shown_radiance(mesh, radiance), options);
        if (*format != ExportFormat::ply) {
            write_gltf_export(temporary, mesh, radiance, options, *format == ExportFormat::glb);
        }
    });
}

}  // namespace rad
