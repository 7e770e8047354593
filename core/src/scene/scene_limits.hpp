#pragma once

#include <cstddef>

namespace rad {

// What one scene file may hold, checked while reading and before anything is allocated for it. A file beyond
// these is damaged or hostile: a real scene this large would not fit a radiosity solve (10 million patches at
// most) anyway, and refusing early keeps a forged count from costing gigabytes.
constexpr std::size_t kMaxSceneFileBytes = std::size_t{1} << 30;
constexpr std::size_t kMaxSceneVertices = 10'000'000;
constexpr std::size_t kMaxSceneFaces = 10'000'000;
constexpr std::size_t kMaxSceneFaceCorners = 40'000'000;  // summed over all faces

// The limits as one value, so the checks can be tried with small ones.
struct SceneFileLimits {
    std::size_t vertices = kMaxSceneVertices;
    std::size_t faces = kMaxSceneFaces;
    std::size_t face_corners = kMaxSceneFaceCorners;
};

// Most corners one face may have; larger polygons are almost certainly damage, and triangulating them costs
// time quadratic in their size.
constexpr std::size_t kMaxFaceCorners = 4096;

// Largest coordinate magnitude a scene file may hold: far beyond any real scene, it keeps the squares (areas)
// and fourth powers (form-factor kernels) of lengths finite.
constexpr double kMaxCoordinate = 1e30;

// Distinct material libraries one OBJ file may name.
constexpr std::size_t kMaxMaterialLibraries = 64;

// Most texels one glTF texture may decode to (an 8192 × 8192 image, 256 MiB as 8-bit RGBA): a larger one
// is not decoded (its material takes its factor alone, with a warning), so a forged image header cannot
// make the decoder allocate gigabytes.
constexpr std::size_t kMaxTextureTexels = std::size_t{1} << 26;

}  // namespace rad
