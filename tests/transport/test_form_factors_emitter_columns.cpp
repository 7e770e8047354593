// The hemisphere estimator leaves the emitters' columns to shadow rays drawn by power
// (form_factors_emitter_columns): those columns are the closed forms where nothing is in the way, agree with
// a far longer hemisphere estimate where something is, share the row's rays when there are many emitter
// patches, and stay with the hemisphere when the emitters are most of the scene.
#include <gtest/gtest.h>

#include <cstdio>

#include "form_factor_test_scenes.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "transport/uniform/form_factors_emitter_columns.hpp"

namespace rad {
namespace {

// Upper square emits: surface 1 of parallel_rectangles.
Scene lit_parallel_squares() {
    Scene scene = test::parallel_rectangles(1.0, 1.0, 1.0);
    scene.surfaces[1].material.emission = glm::dvec3(1.0);
    return scene;
}

FormFactorOptions with_emitters(const Scene& scene, int rays) {
    FormFactorOptions options;
    options.rays = rays;
    options.emitting_surfaces = emitting_surfaces(scene);
    return options;
}

TEST(EmitterColumns, AreTheClosedFormWhereNothingIsInTheWay) {
    const Scene scene = lit_parallel_squares();
    const PatchMesh mesh = test::mesh(scene, 0.25);
    const double exact = test::parallel_rectangles_factor(1, 1, 1);
    const double analytic =
        test::surface_factor(compute_form_factors(mesh, with_emitters(scene, 256)), mesh, 0, 1);
    // Only quadrature and float storage are left; 256 hemisphere rays per patch would be off by about 2 %.
    EXPECT_NEAR(analytic / exact, 1.0, 1e-4) << "F = " << analytic;
    // The emitter's own row is the hemisphere's, and it is not lost.
    const double back =
        test::surface_factor(compute_form_factors(mesh, with_emitters(scene, 4096)), mesh, 1, 0);
    EXPECT_NEAR(back / exact, 1.0, 0.02) << "F = " << back;
}

// The Cornell box's floor sees the light past the two blocks: the shadow rays' visibility agrees with 32
// times the default hemisphere rays, which see the light without help.
TEST(EmitterColumns, SeeTheLightPastOccludersAsTheHemisphereDoes) {
    const Scene scene = make_cornell_box();
    const PatchMesh mesh = test::mesh(scene, 70.0);
    const std::vector<std::uint32_t> lights = emitting_surfaces(scene);
    ASSERT_FALSE(lights.empty());
    FormFactorOptions hemisphere;
    hemisphere.rays = 65536;
    const FormFactorMatrix reference = compute_form_factors(mesh, hemisphere);
    const FormFactorMatrix split = compute_form_factors(mesh, with_emitters(scene, 0));
    std::size_t compared = 0;
    for (std::uint32_t s = 0; s + 1 < mesh.surface_begin.size(); ++s) {
        double to_light_reference = 0.0, to_light_split = 0.0;
        for (std::uint32_t light : lights) {
            to_light_reference += test::surface_factor(reference, mesh, s, light);
            to_light_split += test::surface_factor(split, mesh, s, light);
        }
        if (to_light_reference < 1e-3) continue;  // the light and the ceiling do not see it
        std::printf("[ figures  ] %s to the light: %.5f, hemisphere alone %.5f\n",
                    scene.surfaces[s].name.c_str(), to_light_split, to_light_reference);
        ++compared;
        // Each surface's factor to the light is 0.5-0.9 %: 65536 rays per patch give it 5-25 thousand hits in
        // all, a standard deviation of 0.6-1 %.
        EXPECT_NEAR(to_light_split / to_light_reference, 1.0, 0.03)
            << "surface " << scene.surfaces[s].name << ": " << to_light_split << " against "
            << to_light_reference;
    }
    EXPECT_EQ(compared, 6u) << "surfaces that see the light";
}

// 64 emitter patches and 256 rays per row: 16 draws of 16 shadow rays, a systematic sample by power. Each
// receiver patch's factor to the whole emitter is still the closed form's (within the sample's spread), and
// no row spends more rays on the emitters than its hemisphere has.
TEST(EmitterColumns, ManyEmitterPatchesAreDrawnByTheirPower) {
    const Scene scene = lit_parallel_squares();
    const PatchMesh fine = test::mesh(scene, 1.0 / 8);
    FormFactorReport report;
    const FormFactorMatrix matrix = compute_form_factors(fine, with_emitters(scene, 256), &report);
    const double exact = test::parallel_rectangles_factor(1, 1, 1);
    EXPECT_NEAR(test::surface_factor(matrix, fine, 0, 1) / exact, 1.0, 0.01);
    EXPECT_LE(report.rays, fine.size() * 256u + 64u * 256u);
    EXPECT_GT(report.rays, fine.size() * 256u);
}

// Where the emitters cover most of the scene (a furnace), the hemisphere rays meet them often: every column
// is the hemisphere's, exactly `rays` per patch.
TEST(EmitterColumns, LargeEmittersStayWithTheHemisphere) {
    Scene scene = lit_parallel_squares();
    scene.surfaces[0].material.emission = glm::dvec3(1.0);
    const PatchMesh mesh = test::mesh(scene, 1.0 / 4);
    FormFactorReport report;
    compute_form_factors(mesh, with_emitters(scene, 256), &report);
    EXPECT_EQ(report.rays, mesh.size() * 256u);
    // Escaped counts the hemisphere rays that meet nothing.
    EXPECT_NEAR(report.escaped_ray_fraction, 1.0 - test::parallel_rectangles_factor(1, 1, 1), 0.02);
}

}  // namespace
}  // namespace rad
