#include "light/emitters.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "sampling/emitter_patches.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

// Up to this many emitter patches are drawn from directly; more are drawn in two steps, a chunk of about √N
// neighbouring patches of one surface first, so a vertex weighs about 2 √N of them, not all.
constexpr std::size_t kDirectlyDrawnEmitters = 64;

EmitterChunk make_chunk(const Emitters& e, std::uint32_t begin, std::uint32_t end) {
    EmitterChunk c;
    c.begin = begin;
    c.end = end;
    if (end - begin == 1) {
        c.shape = e.shapes[begin];
        c.luminance = e.luminance[begin];
        return c;
    }
    glm::dvec3 normal(0.0);
    for (std::uint32_t k = begin; k < end; ++k) {
        c.shape.area += e.shapes[k].area;
        c.shape.centroid += e.shapes[k].area * e.shapes[k].centroid;
        normal += e.shapes[k].area * e.shapes[k].normal;
        c.luminance += e.shapes[k].area * e.luminance[k];
    }
    c.shape.centroid /= c.shape.area;
    c.luminance /= c.shape.area;
    for (std::uint32_t k = begin; k < end; ++k) {
        c.shape.radius = std::max(c.shape.radius,
                                  glm::length(e.shapes[k].centroid - c.shape.centroid) + e.shapes[k].radius);
    }
    // Patches facing many ways (a lamp's globe) send light every way: no normal, so no cosine at the source.
    if (glm::length(normal) >= 0.9 * c.shape.area) c.shape.normal = glm::normalize(normal);
    return c;
}

void make_chunks(Emitters& e, const PatchMesh& patches) {
    const std::size_t n = e.patches.size();
    const std::size_t size = n <= kDirectlyDrawnEmitters
                                 ? 1
                                 : static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    for (std::uint32_t begin = 0; begin < n;) {
        std::uint32_t end = begin + 1;
        const std::uint32_t surface = patches.patches[e.patches[begin]].surface;
        while (end < n && end - begin < size && patches.patches[e.patches[end]].surface == surface) ++end;
        e.chunks.push_back(make_chunk(e, begin, end));
        begin = end;
    }
}

double chunk_weight(const glm::dvec3& origin, const glm::dvec3& n, const EmitterChunk& c) {
    return c.luminance * factor_weight(origin, n, 0.0, c.shape);
}

}  // namespace

std::optional<Emitters> find_emitters(const PatchMesh& patches, std::span<const glm::dvec3> emitted) {
    Emitters out;
    for (std::uint32_t q = 0; q < patches.size(); ++q) {
        const double l = luminance(emitted[q]);
        if (!(l > 0.0)) continue;
        out.patches.push_back(q);
        out.luminance.push_back(l);
    }
    if (!sample_emitter_columns(patches, out.patches)) return std::nullopt;
    out.shapes.reserve(out.patches.size());
    for (std::uint32_t q : out.patches) out.shapes.push_back(patch_shape(patches, q));
    make_chunks(out, patches);
    return out;
}

double emitter_weights(const glm::dvec3& origin, const glm::dvec3& n, const Emitters& emitters,
                       std::vector<double>& weight) {
    weight.assign(emitters.chunks.size(), 0.0);
    double total = 0.0;
    for (std::size_t k = 0; k < emitters.chunks.size(); ++k) {
        weight[k] = chunk_weight(origin, n, emitters.chunks[k]);
        total += weight[k];
    }
    return total;
}

}  // namespace rad
