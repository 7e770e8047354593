// A room lit by 400 small lamps (assets/hard/many_lights.obj, from scripts/many_lights.py): more emitter
// patches than a row's rays could give a fixed share each. The emitters' columns are drawn by power, so each
// floor patch's direct light is the exact one (the room is empty: nothing blocks it) within a percent or two,
// and two seeds agree patch by patch, where the hemisphere rays alone leave blotches.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "transport/uniform/form_factors_analytic.hpp"

namespace rad {
namespace {

const std::string kManyLights = std::string(RAD_SOURCE_DIR) + "/assets/hard/many_lights.obj";

struct Room {
    Scene scene = load_scene(kManyLights);
    PatchMesh patches = build_patches(scene, {});
    std::vector<std::uint32_t> lamps = emitting_surfaces(scene);
};

// The direct irradiance per patch of the floor (surface 0), H_i = Σ_j F_ij E_j over the lamps' patches.
std::vector<double> floor_direct_light(const Room& room, const FormFactorMatrix& matrix) {
    std::vector<double> light;
    for (std::uint32_t i = room.patches.surface_begin[0]; i < room.patches.surface_begin[1]; ++i) {
        double h = 0.0;
        const FormFactorRow row = matrix.row(i);
        for (std::size_t k = 0; k < row.columns.size(); ++k) {
            const Surface& s = room.scene.surfaces[room.patches.patches[row.columns[k]].surface];
            h += row.values[k] * s.material.emitted_radiosity().y;
        }
        light.push_back(h);
    }
    return light;
}

// The same without visibility (nothing stands between the floor and the lamps): Σ_j U_ij E_j.
std::vector<double> exact_floor_direct_light(const Room& room) {
    std::vector<double> light;
    const PatchMesh& m = room.patches;
    const auto polygon = [&](std::uint32_t p) {
        ConvexPolygon poly;
        poly.count = static_cast<std::size_t>(m.corner_count(p));
        for (std::size_t k = 0; k < poly.count; ++k) poly.corners[k] = m.points[m.corners[p][k]];
        return poly;
    };
    for (std::uint32_t i = m.surface_begin[0]; i < m.surface_begin[1]; ++i) {
        double h = 0.0;
        for (std::uint32_t j = 0; j < m.size(); ++j) {
            const Material& material = room.scene.surfaces[m.patches[j].surface].material;
            if (!material.emits()) continue;
            h += unoccluded_form_factor(polygon(i), m.patches[i].centroid, m.patches[i].normal,
                                        m.patches[i].area, polygon(j), m.patches[j].normal) *
                 material.emitted_radiosity().y;
        }
        light.push_back(h);
    }
    return light;
}

FormFactorMatrix form_factors(const Room& room, std::uint64_t seed, bool aim_at_emitters) {
    FormFactorOptions options;
    options.seed = seed;
    if (aim_at_emitters) {
        options.emitting_surfaces = room.lamps;
        options.emitted_luminance = emitted_luminance(room.scene, room.lamps);
    }
    return compute_form_factors(room.patches, options);
}

// Root mean square of a / b − 1.
double rms_relative(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) sum += (a[k] / b[k] - 1.0) * (a[k] / b[k] - 1.0);
    return std::sqrt(sum / static_cast<double>(a.size()));
}

TEST(ManyLights, EveryFloorPatchGetsItsExactDirectLight) {
    const Room room;
    ASSERT_EQ(room.lamps.size(), 400u);
    const std::vector<double> exact = exact_floor_direct_light(room);
    const std::vector<double> drawn = floor_direct_light(room, form_factors(room, 1, true));
    const std::vector<double> other_seed = floor_direct_light(room, form_factors(room, 2, true));
    const std::vector<double> hemisphere = floor_direct_light(room, form_factors(room, 1, false));
    const std::vector<double> hemisphere_other = floor_direct_light(room, form_factors(room, 2, false));
    double worst = 0.0;
    for (std::size_t k = 0; k < exact.size(); ++k)
        worst = std::max(worst, std::abs(drawn[k] / exact[k] - 1.0));
    std::printf(
        "[ figures  ] floor direct light against the exact: drawn by power RMS %.2f %% (worst %.2f %%), "
        "hemisphere rays alone RMS %.2f %%; between two seeds: %.2f %% and %.2f %%\n",
        100 * rms_relative(drawn, exact), 100 * worst, 100 * rms_relative(hemisphere, exact),
        100 * rms_relative(drawn, other_seed), 100 * rms_relative(hemisphere, hemisphere_other));
    EXPECT_LT(rms_relative(drawn, exact), 0.005);
    EXPECT_LT(worst, 0.015);
    EXPECT_LT(rms_relative(drawn, other_seed), 0.005);
    // What the hemisphere alone does, for contrast: several times the noise.
    EXPECT_GT(rms_relative(hemisphere, exact), 3 * rms_relative(drawn, exact));
}

}  // namespace
}  // namespace rad
