#pragma once

// What refinement and visibility need to know of a node of the cluster hierarchy, cluster or element alike.
// Private to the library.

#include <glm/vec3.hpp>

#include "rad/geometry/point_polygon_factor.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"
#include "sampling/sampling.hpp"

namespace rad {

struct NodeShape {
    glm::dvec3 centre{0.0};
    double radius = 0.0;  // of a ball around centre that holds the node
    double area = 0.0;
    bool cluster = false;
    glm::dvec3 normal{0.0};             // elements only
    std::array<double, 6> facing{};     // clusters only: see ClusterHierarchy::Cluster
    bool isotropic = false;             // clusters only: a projected share of 1/4 in every direction
    glm::dvec3 lower{0.0}, upper{0.0};  // clusters only: the box
};

// The largest cosine, from an element's centre and normal, towards a corner of a cluster's box: 1 when
// the centre lies in the box, 0 when the whole box is behind the element's plane.
double cosine_to_box(const NodeShape& element, const NodeShape& cluster);

// The area a cluster's surfaces present towards the unit direction d (their fronts facing it).
double projected_area(const std::array<double, 6>& facing, const glm::dvec3& d);

ConvexPolygon element_polygon(const ElementTree& tree, std::uint32_t element);
NodeShape node_shape(const ClusterHierarchy& h, std::uint32_t node);

// The form factor of a transfer from `source` to `receiver`, per unit radiosity of the source and per unit
// area of the receiver: A_s c_s c_r / (π d² + A_s), the disk approximation that stays finite as the two
// draw close, with c = cos θ for an element and the projected share of its contents (six-direction
// summary) for a cluster; 0 when an element faces away from the other. As a bound (`bound`), an element's
// cosine is its largest towards the corners of a cluster's box, or lifted by the other element's extent, so
// a grazing pair is not dismissed; a cluster's share is 1 (its contents may all face the other node); and
// with a cluster at either end the distance is the gap between the two balls (the centres' distance
// understates the light between near parts of large clusters).
double link_factor(const NodeShape& receiver, const NodeShape& source, bool bound);

// The factor of a link (ClusterLink::factor, before visibility): link_factor, but for a cluster receiver
// without its own share, which its surfaces apply each by its cosine.
double transfer_factor(const NodeShape& receiver, const NodeShape& source);

// The form factor from element `receiver` to element `source`, unoccluded: the point-to-polygon factor
// (exact for a point) averaged over four points of the receiver. Accurate where the disk approximation is
// not: near and adjacent elements, which a row of the leaves' gather is mostly made of.
double element_factor(const ElementTree& tree, std::uint32_t receiver, std::uint32_t source);

// A point on the node's surfaces and that surface's normal: for an element, area-uniform; for a cluster, on
// its surfaces by their projected area towards the unit direction `towards` (a base patch so chosen, then
// an area-uniform point on it).
void sample_node(const ClusterHierarchy& h, std::span<const double> patch_area_prefix, std::uint32_t node,
                 const glm::dvec3& towards, RandomStream& random, glm::dvec3& point, glm::dvec3& normal);

}  // namespace rad
