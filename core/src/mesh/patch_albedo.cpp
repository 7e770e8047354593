#include "rad/mesh/patch_albedo.hpp"

#include "scene/face_texcoords.hpp"

namespace rad {

namespace {

// The point at (s, t) in [0, 1]² of patch q: bilinear over a quad's corners; on a triangle the square is
// folded onto it (t scales the edge from corner 0 along s), which spreads the points over its area.
glm::dvec3 point_in_patch(const PatchMesh& mesh, std::size_t q, double s, double t) {
    const glm::uvec4& c = mesh.corners[q];
    const glm::dvec3 &p0 = mesh.points[c[0]], &p1 = mesh.points[c[1]], &p2 = mesh.points[c[2]];
    if (mesh.is_triangle(q)) {
        const double a = std::sqrt(s);
        return p0 + a * ((1.0 - t) * (p1 - p0) + t * (p2 - p0));
    }
    const glm::dvec3& p3 = mesh.points[c[3]];
    return (1 - s) * (1 - t) * p0 + s * (1 - t) * p1 + s * t * p2 + (1 - s) * t * p3;
}

glm::dvec3 textured_albedo(const Surface& surface, const PatchMesh& mesh, std::size_t q) {
    const Texture& texture = *surface.material.texture;
    const SurfaceMesh::FaceHandle face(static_cast<int>(mesh.patches[q].face));
    glm::dvec3 sum(0.0);
    constexpr int n = kPatchAlbedoSamples;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const glm::dvec3 p = point_in_patch(mesh, q, (i + 0.5) / n, (j + 0.5) / n);
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
