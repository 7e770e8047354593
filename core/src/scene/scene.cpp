#include "rad/scene/scene.hpp"

#include <algorithm>
#include <glm/common.hpp>

#include "rad/geometry/polygon.hpp"
#include "util/luminance.hpp"

namespace rad {

void BoundingBox::extend(const glm::dvec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
}

double BoundingBox::largest_extent() const {
    const glm::dvec3 e = extent();
    return std::max({e.x, e.y, e.z});
}

double face_area(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face) {
    std::vector<glm::dvec3> polygon;
    for (auto v : mesh.fv_range(face)) polygon.push_back(to_glm(mesh.point(v)));
    return polygon_area(polygon);
}

double surface_area(const SurfaceMesh& mesh) {
    double area = 0.0;
    for (auto f : mesh.faces()) area += face_area(mesh, f);
    return area;
}

double total_area(const Scene& scene) {
    double area = 0.0;
    for (const Surface& s : scene.surfaces) area += surface_area(s.mesh);
    return area;
}

BoundingBox bounding_box(const Scene& scene) {
    BoundingBox box;
    for (const Surface& s : scene.surfaces) {
        for (auto v : s.mesh.vertices()) box.extend(to_glm(s.mesh.point(v)));
    }
    return box;
}

bool has_emitter(const Scene& scene) {
    return std::any_of(scene.surfaces.begin(), scene.surfaces.end(),
                       [](const Surface& s) { return s.material.emits(); });
}

std::vector<std::uint32_t> emitting_surfaces(const Scene& scene) {
    std::vector<std::uint32_t> surfaces;
    for (std::uint32_t s = 0; s < scene.surfaces.size(); ++s) {
        if (scene.surfaces[s].material.emits()) surfaces.push_back(s);
    }
    return surfaces;
}

std::string no_emitter_warning(const std::string& source) {
    return source +
           ": no material emits light (Ke), so the scene will be black unless a sky or sun lights it";
}

bool has_outside_light(const Scene& scene) {
    return scene.sky.present() || scene.sun.present();
}

std::vector<double> emitted_luminance(const Scene& scene, std::span<const std::uint32_t> surfaces) {
    std::vector<double> out;
    out.reserve(surfaces.size());
    for (std::uint32_t s : surfaces) out.push_back(luminance(scene.surfaces.at(s).material.emission));
    return out;
}

}  // namespace rad
