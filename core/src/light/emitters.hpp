#pragma once

// The emitter patches a point (a display vertex, a sensor) draws the emitters' direct light from. Private to
// the library.

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "sampling/patch_shapes.hpp"

namespace rad {

// Neighbouring emitter patches of one surface [begin, end) in the emitter list, as one source for drawing.
struct EmitterChunk {
    std::uint32_t begin = 0, end = 0;
    PatchShape
        shape;  // centroid, area, the radius of a ball holding them; the normal if they share one, else 0
    double luminance = 0.0;  // area-weighted mean
};

// The patches that emit (in patch order), their shapes and emitted luminance, and their chunks: one per patch
// up to kDirectlyDrawnEmitters of them, else about √N neighbouring patches of one surface each.
struct Emitters {
    std::vector<std::uint32_t> patches;
    std::vector<PatchShape> shapes;
    std::vector<double> luminance;
    std::vector<EmitterChunk> chunks;
};

// The patches with emission `emitted` (E per patch) as sources to draw; nothing where none emits or where
// they are so many, or cover so much of the scene, that the transport leaves their light to hemisphere
// rays (sample_emitter_columns): light from sources that large is smooth.
std::optional<Emitters> find_emitters(const PatchMesh& patches, std::span<const glm::dvec3> emitted);

// Every chunk's weight at a point with unit normal n (its luminance times factor_weight of its shape) (into
// `weight`); returns their sum.
double emitter_weights(const glm::dvec3& origin, const glm::dvec3& n, const Emitters& emitters,
                       std::vector<double>& weight);

}  // namespace rad
