#include "display/patch_texturing.hpp"

#include <cmath>
#include <stdexcept>

#include "scene/face_texcoords.hpp"

namespace rad {

PatchTexturing::PatchTexturing(const PatchMesh& mesh, const DisplayTexturing& texturing)
    : mesh_(mesh), texturing_(texturing) {
    if (!texturing.scene) return;
    if (texturing.reflectance.size() != mesh.size())
        throw std::invalid_argument("display texturing: the reflectance does not have one entry per patch");
    textured_.assign(mesh.size(), 0);
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        const Patch& patch = mesh.patches[q];
        const Surface& surface = texturing.scene->surfaces.at(patch.surface);
        if (!is_textured(surface) || patch.face >= surface.mesh.n_faces()) continue;
        const glm::dvec2 uv =
            texcoord_at(surface.mesh, SurfaceMesh::FaceHandle(static_cast<int>(patch.face)), patch.centroid);
        textured_[q] = std::isfinite(uv.x) && std::isfinite(uv.y) ? 1 : 0;
        any_ = any_ || textured_[q] != 0;
    }
}

glm::vec2 PatchTexturing::texcoord(std::size_t q, const glm::dvec3& point) const {
    if (!textured(q)) return glm::vec2(0.0f);
    const Patch& patch = mesh_.patches[q];
    const Surface& surface = texturing_.scene->surfaces[patch.surface];
    return glm::vec2(texcoord_at(surface.mesh, SurfaceMesh::FaceHandle(static_cast<int>(patch.face)), point));
}

void PatchTexturing::finish(DisplayMesh& display) const {
    if (!any_) {
        display.texcoords.clear();
        return;
    }
    const std::size_t n = display.triangles.size();
    for (std::size_t t = 0; t < n;) {
        const std::uint32_t q = display.triangle_patch[t];
        if (!textured(q)) {
            ++t;
            continue;
        }
        const std::uint32_t surface = mesh_.patches[q].surface;
        std::size_t end = t + 1;
        while (end < n && textured(display.triangle_patch[end]) &&
               mesh_.patches[display.triangle_patch[end]].surface == surface)
            ++end;
        const Material& material = texturing_.scene->surfaces[surface].material;
        display.textured.push_back(
            {static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(end - t), material.texture,
             glm::vec3(albedo_scale(*material.texture, material.reflectance)), glm::vec3(material.emission)});
        t = end;
    }
    display.patch_irradiance.assign(mesh_.size(), {});
    for (std::size_t q = 0; q < mesh_.size(); ++q) {
        if (!textured(q)) continue;
        const glm::dvec3& rho = texturing_.reflectance[q];
        DisplayMesh::PatchIrradiance& p = display.patch_irradiance[q];
        p.textured = true;
        p.emission = texturing_.scene->surfaces[mesh_.patches[q].surface].material.emitted_radiosity();
        for (int c = 0; c < 3; ++c) p.inverse_albedo[c] = rho[c] > 0.0 ? 1.0 / rho[c] : 0.0;
    }
}

}  // namespace rad
