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
        display.textured.push_back({static_cast<std::uint32_t>(t), static_cast<std::uint32_t>(end - t),
                                    texturing_.scene->surfaces[surface].material.texture});
        t = end;
    }
    display.patch_textured = textured_;
    light_textured_patches(display, *texturing_.scene, texturing_.reflectance);
}

void light_textured_patches(DisplayMesh& display, const Scene& scene,
                            std::span<const glm::dvec3> reflectance) {
    display.light.patch_irradiance.clear();
    if (display.patch_textured.empty()) return;
    if (reflectance.size() != display.patch_count)
        throw std::invalid_argument("display texturing: the reflectance does not have one entry per patch");
    for (DisplayMesh::TexturedRange& range : display.textured) {
        const std::uint32_t surface = display.patch_surface[display.triangle_patch[range.first_triangle]];
        const Material& material = scene.surfaces.at(surface).material;
        range.albedo_scale = glm::vec3(albedo_scale(*material.texture, material.reflectance));
        range.emitted_radiance = glm::vec3(material.emission);
    }
    display.light.patch_irradiance.assign(display.patch_count, {});
    for (std::size_t q = 0; q < display.patch_count; ++q) {
        if (!display.textured_patch(static_cast<std::uint32_t>(q))) continue;
        const glm::dvec3& rho = reflectance[q];
        DisplayLight::PatchIrradiance& p = display.light.patch_irradiance[q];
        p.emission = scene.surfaces.at(display.patch_surface[q]).material.emitted_radiosity();
        for (int c = 0; c < 3; ++c) p.inverse_albedo[c] = rho[c] > 0.0 ? 1.0 / rho[c] : 0.0;
    }
}

}  // namespace rad
