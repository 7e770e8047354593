// The Monte Carlo reference: paths traced on the patches' geometry, no form factors. It must reproduce
// closed forms (the furnace, the configuration factors of docs/analytic.md), be deterministic for a seed on
// any number of threads, see what the renderer's camera sees, and agree with the radiosity solution of the
// Cornell box. Tolerances are 5 standard errors of the estimates (with fixed seeds), so a failure means a
// bias, not bad luck.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <iostream>
#include <numbers>
#include <vector>

#include "rad/reference/image_error.hpp"
#include "rad/reference/path_tracer.hpp"
#include "rad/scene/builtin_scenes.hpp"
#include "rad/solve/solver.hpp"
#include "rad/transport/uniform/form_factors.hpp"
#include "rad/transport/uniform/uniform_transport.hpp"

namespace rad {
namespace {

constexpr double kSigmas = 5.0;

struct Meshed {
    Scene scene;
    PatchMesh patches;
};

Meshed mesh(Scene scene, double patch_size) {
    Meshed m{std::move(scene), {}};
    m.patches = build_patches(m.scene, MeshingOptions{.patch_size = patch_size});
    return m;
}

// builtin:cube with every face reflecting ρ and emitting E (radiosity).
Scene furnace_cube(double rho, const glm::dvec3& e) {
    Scene scene = make_cube();
    for (Surface& s : scene.surfaces) {
        s.material.reflectance = glm::dvec3(rho);
        s.material.emission = e / std::numbers::pi;
    }
    return scene;
}

void set_reflectance(Scene& scene, const std::string& surface, double rho) {
    for (Surface& s : scene.surfaces) {
        if (s.name == surface) s.material.reflectance = glm::dvec3(rho);
    }
}

std::vector<glm::dvec3> means(const std::vector<Estimate>& estimates) {
    std::vector<glm::dvec3> m;
    for (const Estimate& e : estimates) m.push_back(e.mean);
    return m;
}

// The area-weighted mean over all patches, with its standard error.
Estimate area_mean(const PatchMesh& patches, const std::vector<Estimate>& estimates) {
    double area = 0.0;
    Estimate total;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const double a = patches.patches[i].area;
        area += a;
        total.mean += a * estimates[i].mean;
        total.standard_error += a * a * estimates[i].standard_error * estimates[i].standard_error;
    }
    total.mean /= area;
    total.standard_error = glm::sqrt(total.standard_error) / area;
    return total;
}

class PathTracerFurnace : public ::testing::TestWithParam<double> {};

// B = E / (1 − ρ) on every patch of a closed cube whose faces all emit E and reflect ρ.
TEST_P(PathTracerFurnace, GivesEOverOneMinusRho) {
    const double rho = GetParam();
    const glm::dvec3 e(1.0, 0.5, 2.0);
    const Meshed cube = mesh(furnace_cube(rho, e), 0.5);
    ASSERT_EQ(cube.patches.size(), 24u);
    const PathTracer tracer(cube.scene, cube.patches, {.seed = 7});
    PathTracerStats stats;
    const std::vector<Estimate> b = tracer.patch_radiosity(rho < 0.7 ? 4000 : 2000, &stats);
    const glm::dvec3 expected = e / (1.0 - rho);
    for (std::size_t i = 0; i < b.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_LT(b[i].standard_error[c], 0.02 * expected[c]) << "patch " << i;
            EXPECT_NEAR(b[i].mean[c], expected[c], kSigmas * b[i].standard_error[c]) << "patch " << i;
        }
    }
    const Estimate all = area_mean(cube.patches, b);
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(all.standard_error[c], 0.005 * expected[c]);
        EXPECT_NEAR(all.mean[c], expected[c], kSigmas * all.standard_error[c]) << "channel " << c;
    }
    EXPECT_EQ(stats.paths, 24u * (rho < 0.7 ? 4000u : 2000u));
    EXPECT_GT(stats.rays, stats.paths);
}

INSTANTIATE_TEST_SUITE_P(Rho, PathTracerFurnace, ::testing::Values(0.5, 0.9));

// One square emits E = 1 and reflects nothing, the other reflects ρ = 0.5: the receiver's area-averaged
// radiosity is ρ F E with F the closed-form configuration factor (docs/analytic.md), and at a corner of the
// receiver it is ρ F_point E with the point-to-polygon factor.
struct ClosedForm {
    const char* scene;
    double patch_factor;  // F from the receiver to the emitter
    glm::dvec3 corner;    // a point of the receiver
    double point_factor;  // from that point to the emitter
};

class PathTracerClosedForm : public ::testing::TestWithParam<ClosedForm> {};

TEST_P(PathTracerClosedForm, ReceiverGetsRhoFE) {
    const ClosedForm& form = GetParam();
    Scene scene = make_builtin_scene(form.scene);
    const std::string emitter = scene.surfaces[0].name, receiver = scene.surfaces[1].name;
    set_reflectance(scene, emitter, 0.0);
    const Meshed m = mesh(std::move(scene), 1.0);
    ASSERT_EQ(m.patches.size(), 2u);
    const PathTracer tracer(m.scene, m.patches, {.seed = 3});
    const std::vector<Estimate> b = tracer.patch_radiosity(400'000);
    EXPECT_EQ(b[0].mean, glm::dvec3(1.0));  // E, and nothing reflected
    EXPECT_EQ(b[0].standard_error, glm::dvec3(0.0));
    const double expected = 0.5 * form.patch_factor;
    EXPECT_LT(b[1].standard_error.x, 0.003 * expected);
    EXPECT_NEAR(b[1].mean.x, expected, kSigmas * b[1].standard_error.x);

    const SurfacePoint corner{form.corner, 1};
    const Estimate at = tracer.radiosity_at(std::span(&corner, 1), 100'000)[0];
    const double expected_at = 0.5 * form.point_factor;
    EXPECT_LT(at.standard_error.x, 0.003 * expected_at);
    EXPECT_NEAR(at.mean.x, expected_at, kSigmas * at.standard_error.x);
}

INSTANTIATE_TEST_SUITE_P(AnalyticMd, PathTracerClosedForm,
                         ::testing::Values(ClosedForm{"parallel", 0.199825, {0.0, 1.0, 0.0}, 0.138532},
                                           ClosedForm{"perpendicular", 0.200044, {0.0, 1.0, 0.0}, 0.055734}),
                         [](const auto& info) { return std::string(info.param.scene); });

// max_depth 0 keeps the start's emission and one reflection of direct light: two parallel squares that
// both reflect ρ = 0.5 give the receiver ρ F E, and the emitter exactly E (the receiver emits nothing).
TEST(PathTracer, MaxDepthZeroGathersDirectLightOnly) {
    const Meshed m = mesh(make_parallel_squares(), 1.0);
    const PathTracer tracer(m.scene, m.patches, {.seed = 5, .max_depth = 0});
    const std::vector<Estimate> b = tracer.patch_radiosity(50'000);
    EXPECT_EQ(b[0].mean, glm::dvec3(1.0));
    EXPECT_NEAR(b[1].mean.x, 0.5 * 0.199825, kSigmas * b[1].standard_error.x);
}

// Without multiple importance sampling (emission reached by bounces is not counted; shadow rays alone find
// it) the estimate is the same within the noise: no light is lost or counted twice either way.
TEST(PathTracer, NextEventEstimationAloneAgrees) {
    Scene scene = make_parallel_squares();
    set_reflectance(scene, "lower", 0.5);
    const Meshed m = mesh(std::move(scene), 0.5);
    const PathTracer with(m.scene, m.patches, {.seed = 9});
    const PathTracer without(m.scene, m.patches, {.seed = 10, .mis = false});
    const std::vector<Estimate> a = with.patch_radiosity(20'000), b = without.patch_radiosity(20'000);
    ASSERT_EQ(a.size(), 8u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double sigma = std::hypot(a[i].standard_error.x, b[i].standard_error.x);
        EXPECT_LT(sigma, 0.01 * a[i].mean.x) << "patch " << i;
        EXPECT_NEAR(a[i].mean.x, b[i].mean.x, kSigmas * sigma) << "patch " << i;
    }
}

// The same seed gives the same bits on one thread and on all; another seed gives other numbers that agree
// within the noise.
TEST(PathTracer, SameSeedSameResultOnAnyNumberOfThreads) {
    const Meshed cornell = mesh(make_cornell_box(), 140.0);
    const PathTracer tracer(cornell.scene, cornell.patches, {.seed = 11});
    const Camera camera = *cornell.scene.camera;
    std::vector<Estimate> single;
    ReferenceImage single_image;
    {
        const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        single = tracer.patch_radiosity(64);
        single_image = tracer.render(camera, 24, 16, 4);
    }
    const std::vector<Estimate> many = tracer.patch_radiosity(64);
    const ReferenceImage many_image = tracer.render(camera, 24, 16, 4);
    for (std::size_t i = 0; i < single.size(); ++i) {
        ASSERT_EQ(single[i].mean, many[i].mean) << "patch " << i;
        ASSERT_EQ(single[i].standard_error, many[i].standard_error) << "patch " << i;
    }
    EXPECT_EQ(single_image.image.pixels, many_image.image.pixels);
    EXPECT_EQ(single_image.standard_error.pixels, many_image.standard_error.pixels);

    const PathTracer other(cornell.scene, cornell.patches, {.seed = 12});
    const std::vector<Estimate> reseeded = other.patch_radiosity(64);
    int differ = 0;
    double z_squared = 0.0;  // Σ of squared differences over their variance: about one per value
    int values = 0;
    for (std::size_t i = 0; i < single.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            differ += single[i].mean[c] != reseeded[i].mean[c];
            const double variance =
                std::pow(single[i].standard_error[c], 2) + std::pow(reseeded[i].standard_error[c], 2);
            if (variance > 0.0) {
                z_squared += std::pow(single[i].mean[c] - reseeded[i].mean[c], 2) / variance;
                ++values;
            }
        }
    }
    EXPECT_GT(differ, static_cast<int>(single.size()));
    ASSERT_GT(values, 100);
    // Heavy-tailed estimates make the standard errors themselves noisy; a bias would show as a mean far
    // above 1.
    EXPECT_LT(z_squared / values, 1.5);
    EXPECT_GT(z_squared / values, 0.5);
}

// Seen from inside the furnace, every pixel is E / (1 − ρ) / π.
TEST(PathTracerImage, FurnaceFromInsideIsUniform) {
    const double rho = 0.5;
    const glm::dvec3 e(1.0, 0.5, 2.0);
    const Meshed cube = mesh(furnace_cube(rho, e), 0.5);
    const PathTracer tracer(cube.scene, cube.patches, {.seed = 1});
    const ReferenceImage result = tracer.render(*cube.scene.camera, 32, 24, 256);
    const Image& image = result.image;
    const Image& standard_error = result.standard_error;
    ASSERT_EQ(image.width, 32);
    ASSERT_EQ(image.height, 24);
    ASSERT_EQ(image.pixels.size(), 32u * 24u);
    ASSERT_EQ(standard_error.pixels.size(), image.pixels.size());
    const glm::dvec3 expected = e / (1.0 - rho) / std::numbers::pi;
    glm::dvec3 sum(0.0), variance(0.0);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_GT(image.pixels[i][c], 0.0f) << "pixel " << i << ": the camera ray missed";
            EXPECT_LT(standard_error.pixels[i][c], 0.05 * expected[c]) << "pixel " << i;
            EXPECT_NEAR(image.pixels[i][c], expected[c], kSigmas * standard_error.pixels[i][c] + 1e-5)
                << "pixel " << i;
        }
        sum += glm::dvec3(image.pixels[i]);
        variance += glm::dvec3(standard_error.pixels[i]) * glm::dvec3(standard_error.pixels[i]);
    }
    const auto n = static_cast<double>(image.pixels.size());
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(sum[c] / n, expected[c], kSigmas * std::sqrt(variance[c]) / n) << "channel " << c;
    }
    EXPECT_EQ(result.stats.paths, 32u * 24u * 256u);

    // The metric: zero against itself, the scale against a scaled copy.
    EXPECT_EQ(block_relative_error(image, image), 0.0);
    Image brighter = image;
    for (glm::vec3& p : brighter.pixels) p *= 1.25f;
    EXPECT_NEAR(block_relative_error(brighter, image), 0.25, 1e-5);
}

// The camera is the renderer's: from the Cornell box's own camera the light is at the top, the red wall on
// the left and the green wall on the right (docs/cornell-box.md), and outside the box's opening there is
// black.
TEST(PathTracerImage, CornellCameraMatchesTheRenderersConvention) {
    const Meshed cornell = mesh(make_cornell_box(), 140.0);
    const PathTracer tracer(cornell.scene, cornell.patches, {.seed = 2});
    const int w = 80, h = 60;  // wider than tall: the aspect must widen the view, not squash it
    const Image image = tracer.render(*cornell.scene.camera, w, h, 4).image;
    // The box's opening spans the image's height; with aspect 4:3 the side columns see past the walls.
    EXPECT_EQ(image.at(0, h / 2), glm::vec3(0.0f));
    EXPECT_EQ(image.at(w - 1, h / 2), glm::vec3(0.0f));
    const glm::vec3 left = image.at(w / 2 - 26, h / 2), right = image.at(w / 2 + 25, h / 2);
    EXPECT_GT(left.r, 2.0f * left.g) << "the red wall should be on the left";
    EXPECT_GT(right.g, 2.0f * right.r) << "the green wall should be on the right";
    // The light, seen directly at the top centre: its radiance Le plus what it reflects.
    const glm::vec3 light = image.at(w / 2, 8);  // the light spans rows 7.4 to 9.5
    EXPECT_GT(light.r, 17.0f);
    EXPECT_LT(light.r, 18.0f);
    const glm::vec3 floor = image.at(w / 2, h - 2);
    EXPECT_LT(floor.r, 0.2f * light.r);
}

// The cross check: on the same mesh, the radiosity solution (hemisphere form factors, direct solve) and
// the path tracer's area-averaged patch radiosities agree. Their difference has three parts: the path
// tracer's noise (known from its standard errors, and taken out), the radiosity method's discretization
// (constant radiosity per patch) and its form-factor error.
TEST(PathTracer, AgreesWithTheRadiositySolutionOfTheCornellBox) {
    const Meshed cornell = mesh(make_cornell_box(), 70.0);
    FormFactorOptions ff;
    ff.rays = 16384;
    const UniformTransport system =
        make_uniform_transport(cornell.scene, cornell.patches, compute_form_factors(cornell.patches, ff));
    auto solver = make_solver(SolverMethod::direct, system, SolverOptions{});
    ASSERT_TRUE(solver->step().converged());
    // The solution is the radiosity of each patch's exposed part; the path tracer averages over the whole
    // patch, including where the blocks cover the floor.
    const std::vector<glm::dvec3> radiosity =
        whole_patch_radiosity(system, cornell.patches, solver->solution());

    const PathTracer tracer(cornell.scene, cornell.patches, {.seed = 1});
    PathTracerStats stats;
    const std::vector<Estimate> traced = tracer.patch_radiosity(2000, &stats);
    const double raw = relative_rms_difference(cornell.patches, radiosity, means(traced));
    // The noise's share of the squared difference: Σ A |SE|² / Σ A |B|².
    double noise = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < traced.size(); ++i) {
        const double a = cornell.patches.patches[i].area;
        noise += a * glm::dot(traced[i].standard_error, traced[i].standard_error);
        norm += a * glm::dot(traced[i].mean, traced[i].mean);
    }
    const double noise_rms = std::sqrt(noise / norm);
    const double corrected = std::sqrt(std::max(0.0, raw * raw - noise_rms * noise_rms));
    std::cout << "Cornell box, " << cornell.patches.size() << " patches, " << stats.paths << " paths in "
              << stats.seconds << " s (" << stats.rays / stats.seconds / 1e6 << " Mrays/s): relative RMS "
              << raw << ", noise " << noise_rms << ", without the noise " << corrected << "\n";
    // Measured: 0.31 % raw, 0.14 % of it noise.
    EXPECT_LT(noise_rms, 0.005);
    EXPECT_LT(corrected, 0.01);
    EXPECT_LT(raw, 0.01);
}

TEST(PathTracer, RejectsBadInput) {
    const Meshed m = mesh(make_parallel_squares(), 1.0);
    EXPECT_THROW(PathTracer(m.scene, m.patches, {.max_survival = 0.0}), std::invalid_argument);
    const PathTracer tracer(m.scene, m.patches);
    EXPECT_THROW(tracer.patch_radiosity(0), std::invalid_argument);
    const SurfacePoint outside{{0.0, 0.0, 0.0}, 7};
    EXPECT_THROW(tracer.radiosity_at(std::span(&outside, 1), 10), std::invalid_argument);
    EXPECT_THROW(tracer.render(Camera{}, 0, 10, 1), std::invalid_argument);
}

TEST(PathTracer, CancelsThroughProgress) {
    const Meshed m = mesh(make_cornell_box(), 70.0);
    const PathTracer tracer(m.scene, m.patches);
    Progress progress;
    progress.cancel();
    EXPECT_THROW(tracer.patch_radiosity(100, nullptr, &progress), Cancelled);
}

}  // namespace
}  // namespace rad
