#include <algorithm>
#include <glm/common.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "rad/display/display_mesh.hpp"
#include "util/luminance.hpp"

namespace rad {

namespace {

// How far beyond the range of its patches a vertex's reconstructed radiosity may go, as a share of that
// range.
constexpr double kReconstructionMargin = 1.0;

// The solution's radiosity on the patches the display is drawn on: itself, or what from_solution makes of
// it (held in `restricted`).
std::span<const glm::dvec3> drawn_radiosity(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                                            std::vector<glm::dvec3>& restricted) {
    if (display.from_solution.empty()) return radiosity;
    restricted = display.from_solution.apply(radiosity);
    return restricted;
}

// direct_light_share over the display's own patches.
double drawn_direct_light_share(const DisplayMesh& display, std::span<const glm::dvec3> radiosity) {
    const DisplayLight::Direct& direct = display.light.direct;
    if (direct.vertex.empty() || radiosity.size() != direct.patch.size()) return 0.0;
    double held = 0.0, full = 0.0;
    for (std::size_t q = 0; q < radiosity.size(); ++q) {
        held += direct.area[q] * luminance(radiosity[q] - direct.emission[q]);
        full += direct.area[q] * luminance(direct.patch[q]);
    }
    return full > 0.0 ? std::clamp(held / full, 0.0, 1.0) : 0.0;
}

// The display's patches' own last bounce over the solution's radiosity `gathered_from`
// (DisplayTraces::patch_gather), with the share of the direct light the vertices do not add themselves.
std::vector<glm::dvec3> patch_gathered(const DisplayMesh& display, std::span<const glm::dvec3> gathered_from,
                                       double direct_share) {
    const GatherTable& rows = display.traced.patch_gather;
    const DisplayLight::PatchGather& light = display.light.patch_gather;
    std::vector<glm::dvec3> out(light.emission);
    for (std::size_t d = 0; d < out.size(); ++d) {
        glm::dvec3 sum(0.0);
        for (std::uint32_t k = rows.row_begin[d]; k < rows.row_begin[d + 1]; ++k) {
            const std::uint32_t q = rows.patch[k];
            sum += static_cast<double>(rows.weight[k]) * (gathered_from[q] - light.source[q]);
        }
        out[d] += light.reflectance[d] * sum;
        if (direct_share > 0.0) out[d] += direct_share * display.light.direct.patch[d];
    }
    return out;
}

// Vertex v's value from the patches around it: their weighted values, kept within the range of the
// patches it is made from, widened by that range. Extrapolation overshoots beside a sharp edge in the
// light, and without bound where a patch's neighbours lie nearly in a line (small elements beside large
// ones); the margin keeps a linear field's border vertices (half a patch or more beyond the last centroid,
// at a T-vertex) exact. Light is never negative.
glm::dvec3 reconstruct(const DisplayMesh& display, std::span<const glm::dvec3> values, std::size_t v) {
    glm::dvec3 sum(0.0), low(std::numeric_limits<double>::infinity()), high(0.0);
    for (std::uint32_t k = display.weight_begin[v]; k < display.weight_begin[v + 1]; ++k) {
        const glm::dvec3& b = values[display.weight_patch[k]];
        sum += static_cast<double>(display.weight[k]) * b;
        low = glm::min(low, b);
        high = glm::max(high, b);
    }
    const glm::dvec3 margin = kReconstructionMargin * (high - low);
    return glm::clamp(sum, glm::max(low - margin, glm::dvec3(0.0)), high + margin);
}

// What vertex v's row gathers: ρ Σ weight (B − source).
glm::dvec3 gathered(const GatherTable& rows, const DisplayLight::Gather& light,
                    std::span<const glm::dvec3> radiosity, std::size_t v) {
    glm::dvec3 sum(0.0);
    for (std::uint32_t k = rows.row_begin[v]; k < rows.row_begin[v + 1]; ++k) {
        const std::uint32_t q = rows.patch[k];
        sum += static_cast<double>(rows.weight[k]) * (radiosity[q] - light.source[q]);
    }
    return light.reflectance[v] * sum;
}

// Every vertex's radiance from the display's patches: `radiosity` as they show it, `gathered_from` what the
// vertices' rows gather, and `share` the direct light the radiosity holds.
void shown_radiance(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                    std::span<const glm::dvec3> gathered_from, double share, bool final_gather,
                    std::span<glm::vec3> radiance) {
    std::vector<glm::dvec3> indirect;
    if (share > 0.0) {
        indirect.resize(radiosity.size());
        for (std::size_t q = 0; q < indirect.size(); ++q)
            indirect[q] = radiosity[q] - share * display.light.direct.patch[q];
        radiosity = indirect;
    }
    // A textured patch contributes the irradiance it receives, which the pixel multiplies by its albedo.
    std::vector<glm::dvec3> irradiance;
    if (!display.light.patch_irradiance.empty()) {
        irradiance.assign(radiosity.begin(), radiosity.end());
        for (std::uint32_t q = 0; q < irradiance.size(); ++q) {
            const DisplayLight::PatchIrradiance& p = display.light.patch_irradiance[q];
            if (display.textured_patch(q))
                irradiance[q] = glm::max(irradiance[q] - p.emission, 0.0) * p.inverse_albedo;
        }
        radiosity = irradiance;
    }
    const GatherTable& rows = display.traced.gather;
    const DisplayLight::Gather& gather = display.light.gather;
    const bool gathers = final_gather && !rows.empty() && !gather.reflectance.empty();
    for (std::size_t v = 0; v < display.vertex_count(); ++v) {
        if (display.weight_begin[v] == display.weight_begin[v + 1]) {
            radiance[v] = glm::vec3(0.0f);  // no patch: no light (and no range to keep within)
            continue;
        }
        const bool row = gathers && rows.row_begin[v] != rows.row_begin[v + 1];
        glm::dvec3 sum =
            row ? reconstruct(display, gather.emission, v) + gathered(rows, gather, gathered_from, v)
                : reconstruct(display, radiosity, v);
        if (share > 0.0) sum += share * glm::dvec3(display.light.direct.vertex[v]);
        radiance[v] = glm::vec3(glm::max(sum, 0.0) / std::numbers::pi);
    }
}

// vertex_radiance from the solution's radiosity, its gathers (the display patches' and the vertices') over
// `gathered_from`.
void solution_radiance(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                       std::span<const glm::dvec3> gathered_from, std::optional<double> direct_share,
                       bool final_gather, std::span<glm::vec3> radiance) {
    if (radiance.size() != display.vertex_count()) {
        throw std::invalid_argument("vertex_radiance: the output does not have one entry per vertex");
    }
    if (radiosity.size() != display.solution_patch_count() || gathered_from.size() != radiosity.size()) {
        throw std::invalid_argument("vertex_radiance: the radiosity does not have one entry per patch");
    }
    std::vector<glm::dvec3> restricted, restricted_from;
    const std::span<const glm::dvec3> drawn = drawn_radiosity(display, radiosity, restricted);
    const std::span<const glm::dvec3> drawn_from = drawn_radiosity(display, gathered_from, restricted_from);
    const double share =
        display.light.direct.vertex.empty()
            ? 0.0
            : std::clamp(direct_share.value_or(drawn_direct_light_share(display, drawn)), 0.0, 1.0);
    if (final_gather && !display.light.patch_gather.emission.empty()) {
        const std::vector<glm::dvec3> patches = patch_gathered(display, gathered_from, share);
        shown_radiance(display, patches, drawn_from, share, final_gather, radiance);
        return;
    }
    shown_radiance(display, drawn, drawn_from, share, final_gather, radiance);
}

}  // namespace

double direct_light_share(const DisplayMesh& display, std::span<const glm::dvec3> radiosity) {
    if (radiosity.size() != display.solution_patch_count()) return 0.0;
    std::vector<glm::dvec3> restricted;
    return drawn_direct_light_share(display, drawn_radiosity(display, radiosity, restricted));
}

void vertex_radiance(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                     std::span<glm::vec3> radiance, std::optional<double> direct_share, bool final_gather) {
    solution_radiance(display, radiosity, radiosity, direct_share, final_gather, radiance);
}

std::vector<glm::vec3> vertex_radiance(const DisplayMesh& display, std::span<const glm::dvec3> radiosity,
                                       std::optional<double> direct_share, bool final_gather) {
    std::vector<glm::vec3> radiance(display.vertex_count());
    solution_radiance(display, radiosity, radiosity, direct_share, final_gather, radiance);
    return radiance;
}

std::vector<glm::vec3> stepped_vertex_radiance(const DisplayMesh& display,
                                               std::span<const glm::dvec3> radiosity,
                                               std::span<const glm::dvec3> previous) {
    std::vector<glm::vec3> radiance(display.vertex_count());
    solution_radiance(display, radiosity, previous, std::nullopt, true, radiance);
    return radiance;
}

}  // namespace rad
