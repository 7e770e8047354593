#pragma once

// Which patches emit, and whether their light is drawn by power (the form factors' emitter columns, the
// clustered transport's aimed direct light and the display's direct light at vertices decide it the same
// way). Private to the library.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// Where the emitters are large (more than this share of the scene's area, as in a furnace) or so many that
// the weights would cost more than the rays, the hemisphere rays meet them often enough: their columns stay
// with the hemisphere estimator.
inline constexpr double kMaxEmitterAreaShare = 0.5;
inline constexpr std::size_t kMaxSampledEmitterPatches = 20'000;

// The patches of the emitting surfaces, sorted.
std::vector<std::uint32_t> emitting_patches(const PatchMesh& patches,
                                            std::span<const std::uint32_t> emitting_surfaces);

// Whether the emitters' columns are drawn by power (above) rather than left to the hemisphere rays.
bool sample_emitter_columns(const PatchMesh& patches, std::span<const std::uint32_t> emitters);

}  // namespace rad
