#include "display/vertex_final_gather.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "display/gather_rows.hpp"
#include "display/vertex_origin.hpp"
#include "ray/ray_offset.hpp"
#include "sampling/sampling.hpp"

namespace rad {

namespace {

// A key of the gather's random streams, apart from every other pass's.
constexpr std::uint64_t kGatherKey = 0x6a7e'f17a'1000'0001ull;

// What one thread's rows are traced with, kept between vertices.
struct Scratch {
    std::vector<Ray> rays;
    std::vector<RayHit> hits;
    std::vector<glm::dvec2> strata;
    std::vector<std::uint32_t> met;
};

// Traces `count` cosine-weighted rays from origin around the frame's normal into s.hits.
void trace_rays(const VertexFinalGatherTraceInput& input, const glm::dvec3& origin, const Frame& frame,
                int count, RandomStream& random, Scratch& s) {
    s.strata.resize(static_cast<std::size_t>(count));
    stratified_square(random, s.strata);
    s.rays.clear();
    for (const glm::dvec2& u : s.strata)
        s.rays.push_back(Ray{origin, 0.0f, frame.to_world(cosine_direction(u))});
    s.hits.resize(s.rays.size());
    input.rays->intersect(s.rays, s.hits);
}

// The edge of the largest patch at vertex v, as the square root of its area.
double vertex_patch_size(const DisplayMesh& display, const PatchMesh& patches, std::size_t v) {
    double area = 0.0;
    for (std::uint32_t k = display.weight_begin[v]; k < display.weight_begin[v + 1]; ++k)
        area = std::max(area, patches.patches[display.weight_patch[k]].area);
    return std::sqrt(area);
}

// Per patch, the size of the input face it is part of: the square root of the face's area.
std::vector<double> face_sizes(const PatchMesh& patches) {
    std::unordered_map<std::uint64_t, double> area;
    for (const Patch& p : patches.patches) area[face_key(p)] += p.area;
    std::vector<double> size(patches.size());
    for (std::size_t q = 0; q < patches.size(); ++q) size[q] = std::sqrt(area[face_key(patches.patches[q])]);
    return size;
}

// Whether a probe ray from origin meets a face (either side) at least kNearFacePatchSizes of vertex v's
// patch size across, within kNearPatchSizes of it.
bool near_a_surface(const DisplayMesh& display, const VertexFinalGatherTraceInput& input,
                    std::span<const double> face_size, const glm::dvec3& origin, const Frame& frame,
                    std::size_t v, RandomStream& random, Scratch& s) {
    trace_rays(input, origin, frame, kNearProbeRays, random, s);
    const double size = vertex_patch_size(display, *input.patches, v);
    for (const RayHit& hit : s.hits) {
        if (hit.met == RayHit::kMissed || static_cast<double>(hit.t) >= kNearPatchSizes * size) continue;
        if (face_size[hit.met] >= kNearFacePatchSizes * size) return true;
    }
    return false;
}

// Vertex v's row: the patches its rays meet from the front, each with its share of the rays.
void gather_row(const DisplayMesh& display, const VertexFinalGatherTraceInput& input,
                std::span<const double> face_size, double offset, int count, std::size_t v, Scratch& s,
                GatherRow& row) {
    const glm::dvec3 normal(display.normals[v]);
    const double length = glm::length(normal);
    if (!(length > 0.0)) return;  // no side to gather on: the vertex keeps its patches' reconstruction
    const glm::dvec3 n = normal / length;
    const glm::dvec3 origin = vertex_origin(display, *input.patches, v) + offset * n;
    const Frame frame = frame_around(n);
    RandomStream random(input.seed ^ kGatherKey, v);
    if (input.near_surfaces_only && !near_a_surface(display, input, face_size, origin, frame, v, random, s))
        return;
    trace_rays(input, origin, frame, count, random, s);
    std::vector<std::uint32_t>& met = s.met;
    met.clear();
    for (const RayHit& hit : s.hits)
        if (hit.patch != RayHit::kMissed && hit.patch != RayHit::kBackFace) met.push_back(hit.patch);
    std::sort(met.begin(), met.end());
    row.patch.clear();
    row.weight.clear();
    const float each = 1.0f / static_cast<float>(count);
    for (std::size_t k = 0; k < met.size(); ++k) {
        if (k > 0 && met[k] == met[k - 1]) {
            row.weight.back() += each;
            continue;
        }
        row.patch.push_back(met[k]);
        row.weight.push_back(each);
    }
}

// The vertex's reflectance: its patches' (one surface's), by their weights.
glm::dvec3 vertex_reflectance(const DisplayMesh& display, std::span<const glm::dvec3> reflectance,
                              std::size_t v) {
    glm::dvec3 sum(0.0);
    double total = 0.0;
    for (std::uint32_t k = display.weight_begin[v]; k < display.weight_begin[v + 1]; ++k) {
        const double w = std::max(0.0f, display.weight[k]);
        sum += w * reflectance[display.weight_patch[k]];
        total += w;
    }
    return total > 0.0 ? sum / total : glm::dvec3(0.0);
}

}  // namespace

void trace_vertex_final_gather(DisplayMesh& display, const VertexFinalGatherTraceInput& input) {
    const PatchMesh& patches = *input.patches;
    if (display.patch_count != patches.size())
        throw std::invalid_argument("trace_vertex_final_gather: the display is not of these patches");
    display.traced.gather = {};
    display.light.gather = {};
    const std::size_t vertices = display.vertex_count();
    if (vertices == 0) return;
    const int most = input.near_surfaces_only ? kNearGatherRays : kFinalGatherRays;
    const int count = static_cast<int>(std::min<std::size_t>(most, input.ray_budget / vertices));
    if (count < (input.near_surfaces_only ? kNearGatherMinRays : kFinalGatherMinRays)) return;
    const double offset = ray_offset(patches);
    const std::vector<double> face_size =
        input.near_surfaces_only ? face_sizes(patches) : std::vector<double>{};
    Progress* progress = input.progress;
    if (progress) {
        progress->begin("final gather at the vertices", vertices);
        progress->note(std::to_string(vertices) + " vertices x " + std::to_string(count) + " rays" +
                       (input.near_surfaces_only ? " where a surface is near" : ""));
    }
    std::vector<GatherRow> rows(vertices);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices, 64),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          Scratch scratch;
                          if (progress && progress->cancelled()) throw Cancelled{};
                          for (std::size_t v = range.begin(); v != range.end(); ++v) {
                              const std::uint32_t first = display.weight_begin[v];
                              if (first == display.weight_begin[v + 1]) continue;
                              if (display.textured_patch(display.weight_patch[first])) continue;
                              gather_row(display, input, face_size, offset, count, v, scratch, rows[v]);
                          }
                          if (progress) progress->advance(range.size());
                      });
    append_rows(rows, display.traced.gather);
}

void light_vertex_final_gather(DisplayMesh& display, const VertexFinalGatherArrays& arrays) {
    const std::size_t n = display.patch_count;
    if (arrays.emission.size() != n || arrays.reflectance.size() != n || arrays.source.size() != n)
        throw std::invalid_argument("light_vertex_final_gather: the arrays do not have one entry per patch");
    DisplayLight::Gather& gather = display.light.gather;
    gather = {};
    if (display.traced.gather.empty()) return;
    gather.reflectance.resize(display.vertex_count());
    for (std::size_t v = 0; v < display.vertex_count(); ++v)
        gather.reflectance[v] = vertex_reflectance(display, arrays.reflectance, v);
    gather.emission.assign(arrays.emission.begin(), arrays.emission.end());
    gather.source.assign(arrays.source.begin(), arrays.source.end());
}

void add_vertex_final_gather(DisplayMesh& display, const VertexFinalGatherInput& input) {
    const std::size_t n = input.patches->size();
    if (input.emission.size() != n || input.reflectance.size() != n || input.source.size() != n ||
        display.patch_count != n) {
        throw std::invalid_argument("add_vertex_final_gather: the arrays do not have one entry per patch");
    }
    trace_vertex_final_gather(display, {.patches = input.patches,
                                        .rays = input.rays,
                                        .seed = input.seed,
                                        .ray_budget = input.ray_budget,
                                        .near_surfaces_only = input.near_surfaces_only,
                                        .progress = input.progress});
    light_vertex_final_gather(
        display, {.emission = input.emission, .reflectance = input.reflectance, .source = input.source});
}

}  // namespace rad
