#include "transport/clustered/cluster_direct_light.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "sampling/patch_shapes.hpp"
#include "transport/clustered/cluster_balance.hpp"
#include "transport/uniform/form_factors_emitter_columns.hpp"
#include "transport/uniform/form_factors_rows.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

// The direct light's random streams, apart from the links' and the reach's.
constexpr std::uint64_t kDirectSeedSalt = 0xd1ec'7119'4700'0001ull;

// Σ_k a_k D_kc per column c, a_k the leaves' exposed areas: what the receivers take of each emitter's light.
std::vector<double> delivered_light(const ClusterHierarchy& h) {
    std::vector<double> delivered(h.direct.emitters.size(), 0.0);
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        const double a = exposed_area(h, k);
        const FormFactorRow row = h.direct.factors.row(k);
        for (std::size_t e = 0; e < row.size(); ++e) delivered[row.columns[e]] += a * row.values[e];
    }
    return delivered;
}

// What each emitter's leaves send to the fronts of surfaces by their reach measure, with its variance, and
// their exposed area.
struct SentLight {
    std::vector<double> front, variance, area;
};

SentLight sent_light(const ClusterHierarchy& h) {
    const std::size_t m = h.direct.emitters.size();
    SentLight sent{std::vector<double>(m, 0.0), std::vector<double>(m, 0.0), std::vector<double>(m, 0.0)};
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        const std::uint32_t c = h.direct.leaf_column[k];
        const double exposed = static_cast<double>(h.exposed[k]);
        if (c == ClusterHierarchy::DirectLight::kNone || !(exposed > 0.0)) continue;
        const double a = exposed_area(h, k);
        const double front = std::min(1.0, static_cast<double>(h.reach[k]) / exposed);
        sent.front[c] += a * front;
        sent.variance[c] += a * a * front * (1.0 - front) / kReachRays;
        sent.area[c] += a;
    }
    return sent;
}

// Scales an emitter's column where the receivers take more or less than its leaves' rays send to the fronts
// of surfaces by more than the noise of that measure (each column apart where its own measure tells; the
// rest, small emitters with few rays each, pooled), and never more than all of its light. The aimed
// factors' own error (a percent on large emitters near their receivers) would otherwise create or lose
// power. Then h.direct.share, per column and unit of its leaves' exposed area.
void normalize_direct_light(ClusterHierarchy& h) {
    ClusterHierarchy::DirectLight& direct = h.direct;
    const std::size_t m = direct.emitters.size();
    const std::vector<double> delivered = delivered_light(h);
    const SentLight sent = sent_light(h);
    std::vector<double> scale(m, 1.0);
    double pooled_delivered = 0.0, pooled_sent = 0.0, pooled_variance = 0.0;
    std::vector<bool> pooled(m, false);
    for (std::size_t c = 0; c < m; ++c) {
        if (!(delivered[c] > 0.0)) continue;
        if (std::abs(delivered[c] - sent.front[c]) > 3.0 * std::sqrt(sent.variance[c])) {
            scale[c] = sent.front[c] / delivered[c];
        } else {
            pooled[c] = true;
            pooled_delivered += delivered[c];
            pooled_sent += sent.front[c];
            pooled_variance += sent.variance[c];
        }
    }
    if (pooled_delivered > 0.0 && std::abs(pooled_delivered - pooled_sent) > 3.0 * std::sqrt(pooled_variance))
        for (std::size_t c = 0; c < m; ++c)
            if (pooled[c]) scale[c] = pooled_sent / pooled_delivered;
    // Never more than all of its light, whatever the noise: the share is the emitter's reach.
    for (std::size_t c = 0; c < m; ++c)
        if (delivered[c] * scale[c] > sent.area[c]) scale[c] = sent.area[c] / delivered[c];
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        const FormFactorRow row = direct.factors.row(k);
        std::span<float> values = direct.factors.row_values(k);
        for (std::size_t e = 0; e < values.size(); ++e)
            values[e] = static_cast<float>(values[e] * scale[row.columns[e]]);
    }
    const std::vector<double> scaled = delivered_light(h);
    direct.share.assign(m, 0.0f);
    for (std::size_t c = 0; c < m; ++c)
        if (sent.area[c] > 0.0) direct.share[c] = static_cast<float>(scaled[c] / sent.area[c]);
}

}  // namespace

std::vector<std::uint32_t> direct_light_emitters(const Scene& scene, const PatchMesh& base) {
    std::vector<std::uint32_t> emitters = emitting_patches(base, emitting_surfaces(scene));
    if (!sample_emitter_columns(base, emitters)) emitters.clear();
    return emitters;
}

void compute_direct_light(ClusterHierarchy& h, const Scene& scene, const PatchMesh& base,
                          std::vector<std::uint32_t> emitters, const RayScene& rays, double offset,
                          int rays_per_leaf, std::uint64_t seed, Progress* progress) {
    ClusterHierarchy::DirectLight& direct = h.direct;
    direct = {};
    if (emitters.empty()) return;
    const std::size_t n = h.leaves.size();
    std::vector<std::uint32_t> column_of(base.size(), ClusterHierarchy::DirectLight::kNone);
    EmitterSet set;
    for (std::uint32_t c = 0; c < emitters.size(); ++c) {
        const std::uint32_t p = emitters[c];
        column_of[p] = c;
        set.shapes.push_back(patch_shape(base, p));
        set.columns.push_back(c);
        set.luminance.push_back(
            luminance(scene.surfaces[base.patches[p].surface].material.emitted_radiosity()));
    }
    direct.leaf_column.resize(n);
    for (std::size_t k = 0; k < n; ++k) direct.leaf_column[k] = column_of[h.tree[h.leaves[k]].base_patch];
    std::vector<std::uint32_t> own(direct.leaf_column.begin(), direct.leaf_column.end());
    const RowFunction row = emitter_rows(patch_shapes(h.leaf_patches), std::move(own), std::move(set), rays,
                                         offset, rays_per_leaf, seed ^ kDirectSeedSalt);
    if (progress) progress->begin("direct light", n);
    RowStats stats;
    direct.factors = assemble_rows(n, row, stats, progress);
    direct.rays = stats.rays;
    // Rays from covered points were blocked: the factors of the exposed part, as the links' are.
    for (std::size_t k = 0; k < n; ++k) {
        const double exposed = static_cast<double>(h.exposed[k]);
        for (float& v : direct.factors.row_values(k))
            v = exposed > 0.0 ? static_cast<float>(static_cast<double>(v) / exposed) : 0.0f;
    }
    direct.emitters = std::move(emitters);
    normalize_direct_light(h);
}

void direct_emission(const ClusterHierarchy& h, std::span<const glm::dvec3> emission,
                     std::span<const glm::dvec3> reflectance, std::span<const glm::dvec3> outside,
                     std::span<glm::dvec3> out) {
    for (std::size_t k = 0; k < out.size(); ++k) {
        if (h.direct.leaf_column[k] == ClusterHierarchy::DirectLight::kNone) {
            out[k] = glm::dvec3(0.0);
            continue;
        }
        const glm::dvec3 reflected = outside.empty() ? glm::dvec3(0.0) : reflectance[k] * outside[k];
        out[k] = glm::max(glm::dvec3(0.0), emission[k] - reflected);
    }
}

void add_direct_light(const ClusterHierarchy& h, std::span<const glm::dvec3> emitted,
                      std::span<glm::dvec3> irradiance) {
    const ClusterHierarchy::DirectLight& direct = h.direct;
    std::vector<glm::dvec3> value(direct.emitters.size(), glm::dvec3(0.0));
    std::vector<double> area(direct.emitters.size(), 0.0);
    for (std::size_t k = 0; k < h.leaves.size(); ++k) {
        const std::uint32_t c = direct.leaf_column[k];
        if (c == ClusterHierarchy::DirectLight::kNone) continue;
        const double a = h.tree[h.leaves[k]].shape.area;
        value[c] += a * emitted[k];
        area[c] += a;
    }
    for (std::size_t c = 0; c < value.size(); ++c)
        if (area[c] > 0.0) value[c] /= area[c];
    tbb::parallel_for(std::size_t(0), h.leaves.size(), [&](std::size_t k) {
        const FormFactorRow row = direct.factors.row(k);
        glm::dvec3 sum(0.0);
        for (std::size_t e = 0; e < row.size(); ++e)
            sum += static_cast<double>(row.values[e]) * value[row.columns[e]];
        irradiance[k] += sum;
    });
}

}  // namespace rad
