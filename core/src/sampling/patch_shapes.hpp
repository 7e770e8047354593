#pragma once

// Patches as polygons, for the analytic estimators (every pair's, the emitters' columns) and for drawing
// light sources by power (the display's direct light). Private to the library.

#include <vector>

#include "geometry/quadrature.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "sampling/sampling.hpp"

namespace rad {

struct PatchShape {
    ConvexPolygon polygon;
    glm::dvec3 centroid{0.0};
    glm::dvec3 normal{0.0};
    double area = 0.0;
    double radius = 0.0;  // of the ball around the centroid that holds the patch
};

PatchShape patch_shape(const PatchMesh& patches, std::size_t patch);
std::vector<PatchShape> patch_shapes(const PatchMesh& patches);

// A weight roughly proportional to the factor from a receiver (a patch, or a point: radius 0) to `source`,
// and positive wherever the exact one can be: the disk approximation A_j c_i c_j / (π g² + A_j) with each
// cosine lifted by the two's extent over their gap g, so a neighbour at a grazing angle is never dismissed;
// a source with no normal (0: parts facing every way) has no cosine. How light sources are weighted when
// they are drawn by power.
double factor_weight(const glm::dvec3& centre, const glm::dvec3& normal, double radius,
                     const PatchShape& source);

// Appends strata.size() / 2 shadow rays from stratified points of `from` to stratified points of `to`,
// each lifted `offset` off its surface along its normal; `strata` is scratch of twice the rays' count.
void append_shadow_rays(const ConvexPolygon& from, const glm::dvec3& from_normal, const ConvexPolygon& to,
                        const glm::dvec3& to_normal, RandomStream& random, double offset,
                        std::vector<glm::dvec2>& strata, std::vector<Ray>& rays);

}  // namespace rad
