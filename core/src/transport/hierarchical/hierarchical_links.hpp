#pragma once

// What one link between two elements carries: the form factor with visibility, and how uncertain it is.
// Private to the library.

#include <cstdint>
#include <vector>

#include "rad/mesh/element_tree.hpp"
#include "rad/ray/ray_scene.hpp"
#include "sampling/sampling.hpp"

namespace rad {

struct LinkEstimate {
    bool facing = false;       // false: the two cannot see each other (facing away, or one wholly covered)
    bool transports = false;   // false: they cannot, or none of the shadow rays arrived
    float factor[4] = {};      // F from receiver to source × visibility, per receiver corner
    float uncertainty = 0.0f;  // see HierarchicalLink::uncertainty
};

// Estimates links between elements of one tree, from any number of threads at once (each with its own
// Scratch). The unoccluded factor is the point-to-polygon factor (exact for the whole source): its mean over
// the receiver by adaptive quadrature, its variation from its values at the receiver's corners, and its
// uncertainty from how far the inner points stray from the interpolation between the corners. Visibility is
// the share of shadow rays between stratified points of the two that arrive; rays are seeded by the pair, so
// estimates do not depend on threads or order.
class LinkEstimator {
  public:
    struct Scratch {
        std::vector<Ray> rays;
        std::vector<std::uint8_t> blocked;
        std::vector<glm::dvec2> strata;
        std::vector<glm::dvec3> from, to;
        std::vector<std::uint8_t> from_covered, to_covered;
    };

    // `exposed_share`: per element, the share other geometry does not cover
    // (HierarchicalSystem::exposed_share).
    LinkEstimator(const ElementTree& tree, const std::vector<float>& exposed_share, const RayScene& scene,
                  double ray_offset, int rays, std::uint64_t seed)
        : tree_(tree),
          exposed_share_(exposed_share),
          scene_(scene),
          offset_(ray_offset),
          rays_(rays),
          seed_(seed) {}

    // `draw` picks an independent set of shadow rays: refinement decides on draw 0 and keeps the factor of
    // draw 1, because keeping the estimate it decided on would favour links whose rays happened to agree
    // (all blocked, or all open: no uncertainty), which biases the light they carry.
    LinkEstimate operator()(std::uint32_t receiver, std::uint32_t source, Scratch& scratch,
                            int draw = 0) const;

    // The share of an element that other geometry does not cover, by coverage probes.
    double exposed_share(std::uint32_t element) const;
    // The element's form factor to the whole scene, times its exposed_share: the share of cosine-weighted
    // rays from stratified points of it that reach the front of some surface (in a closed room 1 where
    // exposed).
    // `escaping` (if given) receives the share of those rays that meet nothing.
    double reaching_share(std::uint32_t element, double* escaping = nullptr) const;

  private:
    // The share of shadow rays between exposed points of the two polygons that arrive; ends on a side
    // marked partly covered are tested and dropped when covered. Negative when no pair of exposed points
    // was drawn.
    double visibility(const ConvexPolygon& from, const glm::dvec3& from_normal, bool from_partly_covered,
                      const ConvexPolygon& to, const glm::dvec3& to_normal, bool to_partly_covered,
                      RandomStream& random, Scratch& scratch) const;

    const ElementTree& tree_;
    const std::vector<float>& exposed_share_;
    const RayScene& scene_;
    double offset_;
    int rays_;
    std::uint64_t seed_;
};

}  // namespace rad
