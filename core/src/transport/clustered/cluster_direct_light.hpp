#pragma once

// The emitters' light straight to every leaf, by shadow rays aimed at the emitters as the uniform transport
// aims them (emitter_rows), instead of through the links. Private to the library.

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "rad/ray/ray_scene.hpp"
#include "rad/transport/clustered/clustered_transport.hpp"

namespace rad {

// The base patches whose surfaces emit, ascending, where their light is better aimed at than linked: none
// where the emitters cover over half the scene or are too many to weigh (sample_emitter_columns), as in a
// furnace, whose links then carry the emission as they carry the rest.
std::vector<std::uint32_t> direct_light_emitters(const Scene& scene, const PatchMesh& base);

// h.direct for the leaves as they stand (h.leaves, h.leaf_patches and h.exposed set): each leaf's factor to
// every emitter base patch, per unit of its exposed area, from about `rays` shadow rays per leaf; each
// emitter's column scaled to deliver what its leaves' measured reach sends.
void compute_direct_light(ClusterHierarchy& h, const Scene& scene, const PatchMesh& base,
                          std::vector<std::uint32_t> emitters, const RayScene& rays, double offset,
                          int rays_per_leaf, std::uint64_t seed, Progress* progress);

// Per leaf, its emitted radiosity where the direct light carries it (a leaf of an emitter base patch), else
// 0: E = emission − ρ H_out, from the transport's arrays.
void direct_emission(const ClusterHierarchy& h, std::span<const glm::dvec3> emission,
                     std::span<const glm::dvec3> reflectance, std::span<const glm::dvec3> outside,
                     std::span<glm::dvec3> out);

// irradiance[k] += Σ_c D_kc E_c, E_c the area-weighted mean of `emitted` over emitter c's leaves.
void add_direct_light(const ClusterHierarchy& h, std::span<const glm::dvec3> emitted,
                      std::span<glm::dvec3> irradiance);

}  // namespace rad
