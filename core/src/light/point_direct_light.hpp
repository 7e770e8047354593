#pragma once

// The emitters' direct light at points (a display's vertices, sensors): exact where a point sees all of it,
// shadow rays drawn by power where it sees part. Private to the library.

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "light/emitters.hpp"
#include "rad/mesh/patch_mesh.hpp"
#include "rad/ray/ray_scene.hpp"

namespace rad {

// Shadow rays per point, drawn over the emitter patches by power.
inline constexpr int kDirectShadowRays = 128;
// A point that sees all of the light takes the exact sum of every emitter patch's unoccluded factor where
// points × emitter patches stay within this many factors; beyond, the draws' estimate, whose spread where
// the patches' factors differ much from their weights (beside a luminous ceiling) streaks the walls.
inline constexpr double kExactFactorBudget = 2e7;

enum class Visibility : std::uint8_t { none, whole, partial };

// H_d at a point, and how much of the light it sees.
struct PointLight {
    glm::dvec3 irradiance{0.0};
    Visibility visibility = Visibility::none;
};

// Whether points that see all of the light take the exact sum over every emitter patch: while `points` ×
// emitter patches stay within the budget.
bool exact_when_open(std::size_t points, const Emitters& emitters, double exact_factor_budget);

// The light at `points` (where rays leave, off their surface by the ray offset) with unit `normals`, from
// `emitters` of `patches` emitting `emitted` (E per patch): at each, the exact unoccluded point-to-polygon
// factor of each emitter patch drawn times the share of its shadow rays that nothing blocks; up to
// kDirectShadowRays rays drawn over the emitters by power (each drawn when they are few), so every value is
// unbiased; 16 first, and the rest only where they disagree (a penumbra); where the 16 all reach the light
// and `exact_when_open`, the exact unoccluded sum over every emitter patch instead. The k-th point draws from
// random stream first_index + k.
std::vector<PointLight> lights_at(const PatchMesh& patches, const RayScene& rays,
                                  std::span<const glm::dvec3> emitted, const Emitters& emitters,
                                  std::span<const glm::dvec3> points, std::span<const glm::dvec3> normals,
                                  std::uint64_t seed, bool exact_when_open, std::size_t first_index = 0);

// Whether patches emitting `emitted` (E per patch) have emitters whose light is traced at points
// (find_emitters), so a caller can skip building rays for a scene that leaves it to the patches (a furnace).
// Throws std::invalid_argument when `emitted` does not have one entry per patch.
bool draws_vertex_direct_light(const PatchMesh& patches, std::span<const glm::dvec3> emitted);

// H_d, the emitters' direct irradiance, at points with unit normals (lights_at's irradiance); 0 everywhere
// where the emitters' light is left to the patches. Throws std::invalid_argument when the sizes do not match.
std::vector<glm::dvec3> direct_irradiance_at(const PatchMesh& patches, const RayScene& rays,
                                             std::span<const glm::dvec3> emitted,
                                             std::span<const glm::dvec3> points,
                                             std::span<const glm::dvec3> normals, std::uint64_t seed = 1,
                                             double exact_factor_budget = kExactFactorBudget);

}  // namespace rad
