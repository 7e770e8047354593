#include "scene/face_texcoords.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

namespace rad {

namespace {

struct Corner {
    glm::dvec3 offset;  // from the point
    double distance = 0.0;
    glm::dvec2 uv;
};

glm::dvec2 no_texcoord() {
    return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

bool is_textured(const Surface& surface) {
    return surface.material.texture != nullptr && surface.mesh.has_halfedge_texcoords2D();
}

glm::dvec2 texcoord_at(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face, const glm::dvec3& point) {
    if (!mesh.has_halfedge_texcoords2D()) return no_texcoord();
    std::vector<Corner> corners;
    glm::dvec3 normal(0.0);
    double size = 0.0;
    for (auto h : mesh.fh_range(face)) {
        const auto uv = mesh.texcoord2D(h);
        Corner c;
        c.offset = to_glm(mesh.point(mesh.to_vertex_handle(h))) - point;
        c.distance = glm::length(c.offset);
        c.uv = glm::dvec2(uv[0], uv[1]);
        if (!std::isfinite(c.uv.x) || !std::isfinite(c.uv.y)) return no_texcoord();
        size = std::max(size, c.distance);
        corners.push_back(c);
    }
    const std::size_t n = corners.size();
    for (std::size_t i = 0; i < n; ++i) normal += glm::cross(corners[i].offset, corners[(i + 1) % n].offset);
    const double tiny = 1e-12 * size;
    // tan(α/2) of the angle each edge spans at the point; on an edge (α = π) the edge's own interpolation.
    std::vector<double> tan_half(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Corner &a = corners[i], &b = corners[(i + 1) % n];
        if (a.distance <= tiny) return a.uv;
        const double along = a.distance * b.distance + glm::dot(a.offset, b.offset);
        const double across = glm::dot(glm::cross(a.offset, b.offset), glm::normalize(normal));
        if (along <= 1e-12 * a.distance * b.distance) {
            const double t = a.distance / (a.distance + b.distance);
            return (1.0 - t) * a.uv + t * b.uv;
        }
        tan_half[i] = across / along;
    }
    glm::dvec2 sum(0.0);
    double weights = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double w = (tan_half[(i + n - 1) % n] + tan_half[i]) / corners[i].distance;
        sum += w * corners[i].uv;
        weights += w;
    }
    if (!(weights > 0.0) || !std::isfinite(weights)) return corners[0].uv;
    return sum / weights;
}

}  // namespace rad
