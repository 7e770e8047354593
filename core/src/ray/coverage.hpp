#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {

// The share of a patch's area that other geometry covers, as a box standing on a floor covers the floor
// under it. A point is covered when probe rays along its normal and in four directions 10° above its plane
// all meet back faces first: from inside a closed object every direction does, while under a single-sided
// sheet (an occluder, a table top seen from below) the grazing rays pass beside it. Stratified over
// kCoverageProbes points; depends only on (seed, patch).
double covered_share(const PatchMesh& patches, const RayScene& scene, std::uint32_t patch, std::uint64_t seed,
                     double offset);

inline constexpr int kCoverageProbes = 256;

// covered[k] = 1 when the point points[k] (already lifted off its surface along `normal`) is covered: its
// probes all meet back faces. The same test as covered_share, point by point.
void covered_points(std::span<const glm::dvec3> points, const glm::dvec3& normal, const RayScene& scene,
                    std::vector<std::uint8_t>& covered);

// The same share for any convex polygon (a hierarchical element), from `probes` stratified points seeded by
// (seed, key).
double covered_share(std::span<const glm::dvec3> polygon, const glm::dvec3& normal, const RayScene& scene,
                     std::uint64_t seed, std::uint64_t key, double offset, int probes);

// covered[i] = covered_share of every patch i, on all cores.
void measure_coverage(const PatchMesh& patches, const RayScene& scene, std::uint64_t seed,
                      std::vector<double>& covered);

}  // namespace rad
