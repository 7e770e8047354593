#include "display/vertex_direct_light.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "display/display_edge_split.hpp"
#include "display/vertex_origin.hpp"
#include "light/emitters.hpp"
#include "rad/display/false_colour.hpp"
#include "rad/scene/scene.hpp"

namespace rad {

namespace {

// A display edge is split where the direct light at its ends differs by more than kShadowEdgeContrast of the
// larger and kShadowEdgeFloor of the vertices' mean, up to kShadowEdgeSplits times, adding at most
// kShadowEdgeBudget new vertices per vertex of the mesh.
constexpr double kShadowEdgeContrast = 0.25;
constexpr double kShadowEdgeFloor = 0.05;
constexpr int kShadowEdgeSplits = 3;
constexpr double kShadowEdgeBudget = 1.0;
// Of the scene's largest extent: an eighth of the default patch size.
constexpr double kShadowEdgeShortest = 1.0 / 128.0;

// The triangles drawn between exact values at their corners do not keep a patch's mean where the light
// curves over it (a chord lies below a concave falloff, above a convex one): each vertex moves by the mean
// of its patches' shortfalls, weighted by the area of its triangles in each, so the patches show about the
// light they hold. Where a shadow's edge crosses a patch its corners keep their own values, and so do
// vertices in umbra: the mean of a step is no value of either side, and the shadow stays sharp.
void keep_patch_means(const DisplayMesh& display, std::span<const glm::dvec3> patch_direct,
                      std::vector<glm::dvec3>& vertex) {
    const std::vector<std::uint8_t>& kept = display.traced.direct_umbra;
    std::vector<glm::dvec3> drawn(display.patch_count, glm::dvec3(0.0));
    std::vector<double> area(display.patch_count, 0.0), triangle_area(display.triangles.size());
    for (std::size_t t = 0; t < display.triangles.size(); ++t) {
        const glm::uvec3& c = display.triangles[t];
        const glm::dvec3 a(display.positions[c[0]]), b(display.positions[c[1]]), d(display.positions[c[2]]);
        triangle_area[t] = 0.5 * glm::length(glm::cross(b - a, d - a));
        const std::uint32_t q = display.triangle_patch[t];
        drawn[q] += triangle_area[t] * (vertex[c[0]] + vertex[c[1]] + vertex[c[2]]) / 3.0;
        area[q] += triangle_area[t];
    }
    std::vector<glm::dvec3> shift(vertex.size(), glm::dvec3(0.0));
    std::vector<double> weight(vertex.size(), 0.0);
    for (std::size_t t = 0; t < display.triangles.size(); ++t) {
        const std::uint32_t q = display.triangle_patch[t];
        if (!(area[q] > 0.0)) continue;
        glm::dvec3 held = patch_direct[q];
        if (display.textured_patch(q)) held *= display.light.patch_irradiance[q].inverse_albedo;
        const glm::dvec3 shortfall = held - drawn[q] / area[q];
        for (int k = 0; k < 3; ++k) {
            shift[display.triangles[t][k]] += triangle_area[t] * shortfall;
            weight[display.triangles[t][k]] += triangle_area[t];
        }
    }
    for (std::size_t v = 0; v < vertex.size(); ++v) {
        if (weight[v] > 0.0 && !kept[v]) vertex[v] += shift[v] / weight[v];
    }
}

// Appends the light at the display's vertices from light.size() on; `exact` as exact_when_open decided for
// the whole display, so the vertices a split adds are traced as the others were.
void add_lights(const DisplayMesh& display, const VertexDirectTraceInput& input, const Emitters& emitters,
                bool exact, std::vector<PointLight>& light) {
    const std::size_t first = light.size(), count = display.vertex_count() - first;
    std::vector<glm::dvec3> origins(count), normals(count);
    for (std::size_t k = 0; k < count; ++k) {
        origins[k] = vertex_origin(display, *input.patches, first + k);
        normals[k] = glm::normalize(glm::dvec3(display.normals[first + k]));
    }
    const std::vector<PointLight> added = lights_at(*input.patches, *input.rays, input.emitted, emitters,
                                                    origins, normals, input.seed, exact, first);
    light.insert(light.end(), added.begin(), added.end());
}

struct ShadowEdge {
    DisplayEdge edge;
    double weight = 0.0;  // the light's step times the edge's length: how much of the image it spans
};

// The interior edges longer than `shortest` across which the direct light changes by more than
// kShadowEdgeContrast of the larger end's and kShadowEdgeFloor of the vertices' mean: a shadow's edge, or a
// contact, between them.
std::vector<ShadowEdge> shadow_edges(const DisplayMesh& display, const std::vector<PointLight>& light,
                                     double shortest) {
    double mean = 0.0;
    for (const PointLight& p : light) mean += rec709_luminance(p.irradiance);
    mean /= static_cast<double>(std::max<std::size_t>(light.size(), 1));
    std::vector<ShadowEdge> edges;
    for (const DisplayEdge& e : interior_edges(display)) {
        const double a = rec709_luminance(light[e.a].irradiance), b = rec709_luminance(light[e.b].irradiance);
        const double step = std::abs(a - b);
        const bool shadowed =
            light[e.a].visibility != Visibility::whole || light[e.b].visibility != Visibility::whole;
        const double length = glm::length(display.positions[e.a] - display.positions[e.b]);
        if (shadowed && length > shortest && step > kShadowEdgeContrast * std::max(a, b) &&
            step > kShadowEdgeFloor * mean)
            edges.push_back({e, step * length});
    }
    return edges;
}

// Splits the display's triangles across shadow edges, kShadowEdgeSplits times at most, each new vertex
// taking its own direct light, within kShadowEdgeBudget new vertices per vertex of the mesh (the edges that
// span most of the image first): the light's steps are drawn at a half, a quarter, an eighth of the patches'
// size instead of across whole triangles, down to an eighth of the default patch size. Where patches are
// already that fine (a clustered room's leaves near the furniture) they resolve the light themselves.
void split_shadow_edges(DisplayMesh& display, const VertexDirectTraceInput& input, const Emitters& emitters,
                        bool exact, std::vector<PointLight>& light) {
    const std::size_t budget =
        display.vertex_count() +
        static_cast<std::size_t>(kShadowEdgeBudget * static_cast<double>(display.vertex_count()));
    BoundingBox box;
    for (const glm::vec3& p : display.positions) box.extend(glm::dvec3(p));
    const double shortest = kShadowEdgeShortest * box.largest_extent();
    for (int round = 0; round < kShadowEdgeSplits && display.vertex_count() < budget; ++round) {
        std::vector<ShadowEdge> edges = shadow_edges(display, light, shortest);
        if (edges.empty()) return;
        const std::size_t room = budget - display.vertex_count();
        if (edges.size() > room) {
            std::nth_element(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(room), edges.end(),
                             [](const ShadowEdge& x, const ShadowEdge& y) { return x.weight > y.weight; });
            edges.resize(room);
        }
        std::vector<DisplayEdge> split(edges.size());
        for (std::size_t k = 0; k < edges.size(); ++k) split[k] = edges[k].edge;
        split_display_edges(display, split);
        add_lights(display, input, emitters, exact, light);
    }
}

}  // namespace

void trace_vertex_direct_light(DisplayMesh& display, const VertexDirectTraceInput& input) {
    const PatchMesh& patches = *input.patches;
    if (input.emitted.size() != patches.size() || display.patch_count != patches.size())
        throw std::invalid_argument(
            "trace_vertex_direct_light: the emission does not have one entry per patch");
    display.traced.direct_irradiance.clear();
    display.traced.direct_umbra.clear();
    display.light.direct = {};
    display.traced.direct_emitted.assign(input.emitted.begin(), input.emitted.end());
    const std::optional<Emitters> emitters = find_emitters(patches, input.emitted);
    if (!emitters) return;
    const bool exact_sums = exact_when_open(display.vertex_count(), *emitters, kExactFactorBudget);
    std::vector<PointLight> light;
    add_lights(display, input, *emitters, exact_sums, light);
    if (input.split_shadow_edges) split_shadow_edges(display, input, *emitters, exact_sums, light);
    DisplayTraces& traced = display.traced;
    traced.direct_irradiance.resize(light.size());
    traced.direct_umbra.resize(light.size());
    for (std::size_t v = 0; v < light.size(); ++v) {
        traced.direct_irradiance[v] = light[v].irradiance;
        traced.direct_umbra[v] = light[v].visibility == Visibility::none ? 1 : 0;
    }
}

void light_vertex_direct_light(DisplayMesh& display, const VertexDirectLightArrays& arrays) {
    const std::size_t n = display.patch_count;
    if (arrays.emission.size() != n || arrays.reflectance.size() != n || arrays.area.size() != n ||
        arrays.patch_direct.size() != n) {
        throw std::invalid_argument("light_vertex_direct_light: the arrays do not have one entry per patch");
    }
    display.light.direct = {};
    const std::vector<glm::dvec3>& irradiance = display.traced.direct_irradiance;
    if (irradiance.empty()) return;
    std::vector<glm::dvec3> exact(display.vertex_count(), glm::dvec3(0.0));
    for (std::size_t v = 0; v < display.vertex_count(); ++v) {
        if (display.weight_begin[v] == display.weight_begin[v + 1]) continue;
        const std::uint32_t q = display.weight_patch[display.weight_begin[v]];
        exact[v] = display.textured_patch(q) ? irradiance[v] : arrays.reflectance[q] * irradiance[v];
    }
    if (arrays.keep_patch_means) keep_patch_means(display, arrays.patch_direct, exact);
    DisplayLight::Direct& direct = display.light.direct;
    direct.vertex.resize(display.vertex_count());
    for (std::size_t v = 0; v < exact.size(); ++v) direct.vertex[v] = glm::vec3(glm::max(exact[v], 0.0));
    direct.patch.assign(arrays.patch_direct.begin(), arrays.patch_direct.end());
    direct.emission.assign(arrays.emission.begin(), arrays.emission.end());
    direct.area.assign(arrays.area.begin(), arrays.area.end());
}

void add_vertex_direct_light(DisplayMesh& display, const VertexDirectLightInput& input) {
    const std::size_t n = input.patches->size();
    if (input.emission.size() != n || input.reflectance.size() != n || input.area.size() != n ||
        input.patch_direct.size() != n) {
        throw std::invalid_argument("add_vertex_direct_light: the arrays do not have one entry per patch");
    }
    trace_vertex_direct_light(display, {.patches = input.patches,
                                        .rays = input.rays,
                                        .emitted = input.emitted,
                                        .seed = input.seed,
                                        .split_shadow_edges = input.split_shadow_edges});
    light_vertex_direct_light(display, {.emission = input.emission,
                                        .reflectance = input.reflectance,
                                        .area = input.area,
                                        .patch_direct = input.patch_direct,
                                        .keep_patch_means = input.keep_patch_means});
}

}  // namespace rad
