#include "display/vertex_emitters.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "transport/uniform/form_factors_emitter_columns.hpp"
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
    // Patches facing many ways (a lamp's globe) send light every way: no cosine at the source.
    c.facing_one_way = glm::length(normal) >= 0.9 * c.shape.area;
    c.shape.normal = c.facing_one_way ? glm::normalize(normal) : glm::dvec3(0.0);
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

double chunk_weight(const glm::dvec3& origin, const glm::dvec3& n, const Emitters& emitters,
                    const EmitterChunk& c) {
    if (c.end - c.begin == 1)
        return emitters.luminance[c.begin] * factor_weight(origin, n, 0.0, emitters.shapes[c.begin]);
    const glm::dvec3 d = c.shape.centroid - origin;
    const double distance = glm::length(d);
    const double gap = std::max(0.0, distance - c.shape.radius);
    const double lift = gap > 0.0 ? c.shape.radius / gap : 1.0;
    const glm::dvec3 towards = distance > 0.0 ? d / distance : n;
    const double ci = std::clamp(glm::dot(n, towards) + lift, 0.0, 1.0);
    const double cj =
        c.facing_one_way ? std::clamp(-glm::dot(c.shape.normal, towards) + lift, 0.0, 1.0) : 1.0;
    return c.luminance * c.shape.area * ci * cj / (std::numbers::pi * gap * gap + c.shape.area);
}

double emitter_weights(const glm::dvec3& origin, const glm::dvec3& n, const Emitters& emitters,
                       std::vector<double>& weight) {
    weight.assign(emitters.chunks.size(), 0.0);
    double total = 0.0;
    for (std::size_t k = 0; k < emitters.chunks.size(); ++k) {
        weight[k] = chunk_weight(origin, n, emitters, emitters.chunks[k]);
        total += weight[k];
    }
    return total;
}

}  // namespace rad
