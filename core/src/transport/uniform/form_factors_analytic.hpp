#pragma once

#include <cstdint>
#include <span>

#include "geometry/quadrature.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"
#include "transport/uniform/form_factors_rows.hpp"

namespace rad {

// F_ij = V_ij (1/A_i) ∫_Qi F(x -> Rj) dA(x), where Rj is patch j clipped to the front of patch i's plane, Qi
// is patch i clipped to the front of patch j's plane, F(x -> Rj) is Lambert's point-to-polygon factor,
// integrated adaptively, and V_ij is the share of `rays` shadow rays between Qi and Rj that nothing blocks.
// Those rays depend on the unordered pair only and always run from the lower index to the higher, so
// V_ij = V_ji exactly and reciprocity errors come from the quadrature alone.
// (1/receiver_area) ∫ over receiver_part of F(x -> source), integrated adaptively: the unoccluded factor
// analytic_rows uses, for any two planar convex polygons (source already clipped to the front of the
// receiver's plane, receiver_part to the front of the source's).
double unoccluded_form_factor(const ConvexPolygon& receiver_part, const glm::dvec3& receiver_centroid,
                              const glm::dvec3& receiver_normal, double receiver_area,
                              const ConvexPolygon& source, const glm::dvec3& source_normal,
                              const AdaptiveRule& rule = {});

RowFunction analytic_rows(const PatchMesh& patches, const RayScene& scene, int rays, std::uint64_t seed,
                          const AdaptiveRule& rule = {});

}  // namespace rad
