#pragma once

// Stratified cosine-weighted rays leaving a patch: the form factors' hemisphere estimator, the coverage
// probes and the display's patch gather all draw them. Private to the library.

#include <cstdint>
#include <span>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {

// The rays for one patch: origins stratified over the patch (bilinear map for quads,
// an area-uniform map for triangles) paired at random with stratified cosine-weighted directions. weights[k]
// is the bilinear map's Jacobian at ray k over the patch's area (1 for parallelograms and triangles), which
// makes the estimate exact in expectation for any quad. The rays depend only on (seed, patch).
void hemisphere_rays(const PatchMesh& patches, std::uint32_t patch, std::uint64_t seed, double offset,
                     std::span<Ray> rays, std::span<double> weights);

}  // namespace rad
