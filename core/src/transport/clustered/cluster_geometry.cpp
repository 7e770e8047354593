#include "transport/clustered/cluster_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <numbers>

namespace rad {

ConvexPolygon element_polygon(const ElementTree& tree, std::uint32_t element) {
    const Element& e = tree[element];
    ConvexPolygon polygon;
    polygon.count = e.is_triangle() ? 3 : 4;
    for (std::size_t k = 0; k < polygon.count; ++k) polygon.corners[k] = tree.points()[e.corners[k]];
    return polygon;
}

NodeShape node_shape(const ClusterHierarchy& h, std::uint32_t node) {
    NodeShape shape;
    const std::uint32_t index = ClusterNode::index(node);
    if (ClusterNode::is_cluster(node)) {
        const ClusterHierarchy::Cluster& c = h.clusters[index];
        shape.centre = c.centre;
        shape.radius = c.radius;
        shape.area = c.area;
        shape.cluster = true;
        shape.facing = c.facing;
        shape.isotropic = h.isotropic;
        shape.lower = c.lower;
        shape.upper = c.upper;
        return shape;
    }
    const Element& e = h.tree[index];
    shape.centre = e.shape.centroid;
    shape.area = e.shape.area;
    shape.normal = e.shape.normal;
    const ConvexPolygon polygon = element_polygon(h.tree, index);
    for (std::size_t k = 0; k < polygon.count; ++k)
        shape.radius = std::max(shape.radius, glm::length(polygon.corners[k] - shape.centre));
    return shape;
}

double cosine_to_box(const NodeShape& element, const NodeShape& cluster) {
    const glm::dvec3 p = element.centre;
    if (glm::all(glm::greaterThanEqual(p, cluster.lower)) && glm::all(glm::lessThanEqual(p, cluster.upper)))
        return 1.0;
    double best = 0.0;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner((k & 1) ? cluster.upper.x : cluster.lower.x,
                                (k & 2) ? cluster.upper.y : cluster.lower.y,
                                (k & 4) ? cluster.upper.z : cluster.lower.z);
        const glm::dvec3 d = corner - p;
        const double length = glm::length(d);
        if (length > 0.0) best = std::max(best, glm::dot(element.normal, d) / length);
    }
    return best;
}

double projected_area(const std::array<double, 6>& facing, const glm::dvec3& d) {
    return std::abs(d.x) * facing[d.x >= 0.0 ? 0 : 1] + std::abs(d.y) * facing[d.y >= 0.0 ? 2 : 3] +
           std::abs(d.z) * facing[d.z >= 0.0 ? 4 : 5];
}

double transfer_factor(const NodeShape& receiver, const NodeShape& source) {
    if (!receiver.cluster) return link_factor(receiver, source, false);
    NodeShape facing = receiver;
    facing.cluster = false;  // a surface facing the source: cosine 1
    facing.normal = source.centre - receiver.centre;
    const double length = std::sqrt(facing.normal.x * facing.normal.x + facing.normal.y * facing.normal.y +
                                    facing.normal.z * facing.normal.z);
    if (!(length > 0.0)) return 0.0;
    facing.normal /= length;
    return link_factor(facing, source, false);
}

double link_factor(const NodeShape& receiver, const NodeShape& source, bool bound) {
    const glm::dvec3 d = source.centre - receiver.centre;
    const double distance2 = glm::dot(d, d);
    const double distance = std::sqrt(distance2);
    const glm::dvec3 direction = distance > 0.0 ? d / distance : glm::dvec3(0.0);
    auto cosine = [&](const NodeShape& at, const glm::dvec3& towards, const NodeShape& other) {
        const double other_radius = other.radius;
        // A cluster's contents may all face the other node: as a bound its share is 1.
        if (at.cluster && !bound && at.isotropic) return 0.25;
        if (at.cluster) return bound ? 1.0 : std::min(1.0, projected_area(at.facing, towards) / at.area);
        const double c = glm::dot(at.normal, towards);
        if (bound && other.cluster) return cosine_to_box(at, other);
        const double lift = !bound ? 0.0 : distance > 0.0 ? std::min(1.0, other_radius / distance) : 1.0;
        return std::clamp(c + lift, 0.0, 1.0);
    };
    const double c_r = cosine(receiver, direction, source);
    const double c_s = cosine(source, -direction, receiver);
    // As a bound, the kernel at the two balls' nearest approach: the centres' distance understates the
    // light between near parts of large nodes.
    const bool clusters = receiver.cluster || source.cluster;
    const double gap =
        bound && clusters ? std::max(0.0, distance - receiver.radius - source.radius) : distance;
    return source.area * c_r * c_s / (std::numbers::pi * gap * gap + source.area);
}

double element_factor(const ElementTree& tree, std::uint32_t receiver, std::uint32_t source) {
    const ConvexPolygon to = element_polygon(tree, source), at = element_polygon(tree, receiver);
    const glm::dvec3 n = tree[receiver].shape.normal;
    // Four points of a 2 × 2 grid over the receiver: a near source's factor varies across it.
    constexpr double kGrid[2] = {0.25, 0.75};
    double sum = 0.0;
    for (const double u : kGrid)
        for (const double v : kGrid) {
            const glm::dvec3 x = point_on_convex_polygon(at.span(), glm::dvec2(u, v));
            const ConvexPolygon front = clip_to_front(to, x, n);
            if (!front.empty()) sum += std::max(0.0, point_polygon_factor(x, n, front.span()));
        }
    return sum / 4.0;
}

void sample_node(const ClusterHierarchy& h, std::span<const double> patch_area_prefix, std::uint32_t node,
                 const glm::dvec3& towards, RandomStream& random, glm::dvec3& point, glm::dvec3& normal) {
    std::uint32_t element = ClusterNode::index(node);
    if (ClusterNode::is_cluster(node)) {
        // A base patch by its area, kept with probability its cosine towards the other node (rejection):
        // the surfaces facing away send nothing there, and rays from them would meet the cluster itself.
        constexpr int kTries = 8;
        const ClusterHierarchy::Cluster& c = h.clusters[element];
        const double low = patch_area_prefix[c.patch_begin], high = patch_area_prefix[c.patch_end];
        for (int attempt = 0; attempt < kTries; ++attempt) {
            const double pick = low + random.uniform() * (high - low);
            const auto it = std::upper_bound(patch_area_prefix.begin() + c.patch_begin + 1,
                                             patch_area_prefix.begin() + c.patch_end, pick);
            const auto slot = static_cast<std::size_t>(it - patch_area_prefix.begin()) - 1;
            element = h.patch_order[std::min<std::size_t>(slot, c.patch_end - 1)];
            if (random.uniform() < glm::dot(h.tree[element].shape.normal, towards)) break;
        }
    }
    const ConvexPolygon polygon = element_polygon(h.tree, element);
    point = point_on_convex_polygon(polygon.span(), glm::dvec2(random.uniform(), random.uniform()));
    normal = h.tree[element].shape.normal;
}

}  // namespace rad
