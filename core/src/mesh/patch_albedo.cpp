#include "rad/mesh/patch_albedo.hpp"

#include <array>

#include "sampling/sampling.hpp"
#include "scene/face_texcoords.hpp"

namespace rad {

namespace {

glm::dvec3 textured_albedo(const Surface& surface, const PatchMesh& mesh, std::size_t q) {
    const Texture& texture = *surface.material.texture;
    const SurfaceMesh::FaceHandle face(static_cast<int>(mesh.patches[q].face));
    std::array<glm::dvec3, 4> corners;
    const auto count = static_cast<std::size_t>(mesh.corner_count(q));
    for (std::size_t k = 0; k < count; ++k) corners[k] = mesh.points[mesh.corners[q][k]];
    const std::span<const glm::dvec3> polygon(corners.data(), count);
    glm::dvec3 sum(0.0);
    constexpr int n = kPatchAlbedoSamples;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 p = point_on_convex_polygon(polygon, glm::dvec2((i + 0.5) / n, (j + 0.5) / n));
            sum += texture.linear_at(texcoord_at(surface.mesh, face, p));
        }
    }
    return albedo_scale(texture, surface.material.reflectance) * sum / double(n * n);
}

}  // namespace

std::vector<glm::dvec3> patch_albedo(const Scene& scene, const PatchMesh& patches) {
    std::vector<glm::dvec3> albedo;
    albedo.reserve(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q) {
        const Surface& surface = scene.surfaces.at(patches.patches[q].surface);
        const bool textured = is_textured(surface) && patches.patches[q].face < surface.mesh.n_faces();
        albedo.push_back(textured ? textured_albedo(surface, patches, q) : surface.material.reflectance);
    }
    return albedo;
}

}  // namespace rad
