#include "sampling/patch_shapes.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <numbers>

namespace rad {

PatchShape patch_shape(const PatchMesh& patches, std::size_t i) {
    const glm::uvec4& c = patches.corners[i];
    PatchShape s;
    s.polygon.count = static_cast<std::size_t>(patches.corner_count(i));
    for (std::size_t k = 0; k < s.polygon.count; ++k) s.polygon.corners[k] = patches.points[c[k]];
    s.centroid = patches.patches[i].centroid;
    s.normal = patches.patches[i].normal;
    s.area = patches.patches[i].area;
    for (std::size_t k = 0; k < s.polygon.count; ++k)
        s.radius = std::max(s.radius, glm::length(s.polygon.corners[k] - s.centroid));
    return s;
}

std::vector<PatchShape> patch_shapes(const PatchMesh& patches) {
    std::vector<PatchShape> shapes(patches.size());
    for (std::size_t i = 0; i < patches.size(); ++i) shapes[i] = patch_shape(patches, i);
    return shapes;
}

double factor_weight(const glm::dvec3& centre, const glm::dvec3& normal, double radius,
                     const PatchShape& source) {
    const glm::dvec3 d = source.centroid - centre;
    const double distance = glm::length(d);
    if (!(distance > 0.0)) return 0.0;
    const glm::dvec3 towards = d / distance;
    const double gap = std::max(0.0, distance - radius - source.radius);
    const double lift = gap > 0.0 ? (radius + source.radius) / gap : 1.0;
    const double ci = std::clamp(glm::dot(normal, towards) + lift, 0.0, 1.0);
    const bool facing = source.normal != glm::dvec3(0.0);
    const double cj = facing ? std::clamp(-glm::dot(source.normal, towards) + lift, 0.0, 1.0) : 1.0;
    return source.area * ci * cj / (std::numbers::pi * gap * gap + source.area);
}

void append_shadow_rays(const ConvexPolygon& from, const glm::dvec3& from_normal, const ConvexPolygon& to,
                        const glm::dvec3& to_normal, RandomStream& random, double offset,
                        std::vector<glm::dvec2>& strata, std::vector<Ray>& rays) {
    const std::size_t count = strata.size() / 2;
    stratified_square(random, std::span(strata).first(count));
    stratified_square(random, std::span(strata).last(count));
    for (std::size_t k = 0; k < count; ++k) {
        const glm::dvec3 a = point_on_convex_polygon(from.span(), strata[k]) + offset * from_normal;
        const glm::dvec3 b = point_on_convex_polygon(to.span(), strata[count + k]) + offset * to_normal;
        rays.push_back(Ray{a, 0.0f, b - a, 1.0f});
    }
}

}  // namespace rad
