// The viewer's material edits: a reflectance or an emitter changed on a solved scene, the solver continued
// from the solution as it stood with the same form factors, reaches what a fresh solve of the edited file
// gives, and balances its energy; a bad value is refused with the material's name. The display after an
// edit of colours or of the sky keeps its geometry and shows what a new display would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pipeline/radiosity_pipeline.hpp"
#include "rad/util/error.hpp"
#include "test_support.hpp"

namespace rad {
namespace {

constexpr const char* kMaterials =
    "newmtl white\nKd 0.725 0.71 0.68\nnewmtl red\nKd %RED%\nnewmtl green\nKd 0.14 0.45 0.091\n"
    "newmtl light\nKd 0.78 0.78 0.78\nKe %LIGHT%\n";

std::string materials(const std::string& red, const std::string& light) {
    std::string text = kMaterials;
    text.replace(text.find("%RED%"), 5, red);
    text.replace(text.find("%LIGHT%"), 7, light);
    return text;
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The Cornell box OBJ in `folder`/`name`/, with these materials.
std::string cornell_with(const test::TempDir& folder, const std::string& name, const std::string& mtl) {
    std::filesystem::create_directories(folder.path() / name);
    const std::string obj = read_file(std::filesystem::path(RAD_SOURCE_DIR) / "assets" / "cornell_box.obj");
    folder.write(name + "/cornell_box.mtl", mtl);
    return folder.write(name + "/cornell_box.obj", obj);
}

PipelineOptions options_for(const std::string& scene, const std::string& subdivision) {
    PipelineOptions options;
    options.scene.scene = scene;
    options.scene.patch_size = 100.0;
    options.subdivision.method = subdivision;
    options.solver.method = "jacobi";
    options.solver.tolerance = 1e-9;
    return options;
}

double relative_rms(const RadiosityPipeline& a, const RadiosityPipeline& b) {
    const auto x = a.solver().solution();
    const auto y = b.solver().solution();
    EXPECT_EQ(x.size(), y.size());
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
        const double area = a.transport().area[i];
        const glm::dvec3 d = x[i] - y[i];
        difference += area * (d.x * d.x + d.y * d.y + d.z * d.z);
        norm += area * (y[i].x * y[i].x + y[i].y * y[i].y + y[i].z * y[i].z);
    }
    return std::sqrt(difference / norm);
}

double relative_imbalance(const RadiosityPipeline& pipeline) {
    const EnergyBalance balance = pipeline.energy_balance();
    const glm::dvec3 off = balance.imbalance();
    const glm::dvec3 in = balance.emitted + balance.outside;
    return std::abs(off.x + off.y + off.z) / (in.x + in.y + in.z);
}

TEST(MaterialEdit, ContinuingAfterAnEditReachesTheFreshSolveOfTheEditedFile) {
    const test::TempDir folder;
    const std::string original = cornell_with(folder, "original", materials("0.63 0.065 0.05", "17 12 4"));
    const std::string edited = cornell_with(folder, "edited", materials("0.2 0.5 0.7", "8 12 16"));

    RadiosityPipeline continued(options_for(original, "uniform"));
    continued.solve();
    continued.edit_material("red", {0.2, 0.5, 0.7}, {0.0, 0.0, 0.0});
    continued.edit_material("light", {0.78, 0.78, 0.78}, {8.0, 12.0, 16.0});
    ASSERT_EQ(continued.solver().report().step, 0u);  // a fresh solver, from the solution as it stood
    continued.solve();

    RadiosityPipeline fresh(options_for(edited, "uniform"));
    fresh.solve();
    EXPECT_EQ(continued.work().form_factor_passes, 1u);
    EXPECT_LT(relative_rms(continued, fresh), 1e-6);
    EXPECT_LT(relative_imbalance(continued), 0.005);
}

TEST(MaterialEdit, ClusteredLinksStayAndTheEnergyBalances) {
    const test::TempDir folder;
    const std::string original = cornell_with(folder, "original", materials("0.63 0.065 0.05", "17 12 4"));
    RadiosityPipeline pipeline(options_for(original, "clustered"));
    pipeline.solve();
    const glm::dvec3 before = pipeline.energy_balance().emitted;
    pipeline.edit_material("light", {0.78, 0.78, 0.78}, {34.0, 24.0, 8.0});  // twice the light
    pipeline.solve();
    EXPECT_EQ(pipeline.work().form_factor_passes, 1u);
    const glm::dvec3 after = pipeline.energy_balance().emitted;
    EXPECT_NEAR(after.x / before.x, 2.0, 1e-9);
    EXPECT_LT(relative_imbalance(pipeline), 0.005);
}

TEST(MaterialEdit, BadValuesAndUnknownNamesAreRefusedWithTheName) {
    RadiosityPipeline pipeline(options_for("builtin:cornell", "uniform"));
    pipeline.prepare();
    const auto message = [&](const std::string& name, glm::dvec3 rho, glm::dvec3 le) {
        try {
            pipeline.edit_material(name, rho, le);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message("white", glm::dvec3(1.2), glm::dvec3(0.0)).find("white"), std::string::npos);
    EXPECT_NE(message("white", glm::dvec3(0.5), glm::dvec3(-1.0)).find("white"), std::string::npos);
    EXPECT_NE(message("no such", glm::dvec3(0.5), glm::dvec3(0.0)).find("no such"), std::string::npos);
}

// The largest difference between two displays' radiance for the pipeline's solution as it stands.
double largest_difference(const RadiosityPipeline& pipeline, const DisplayMesh& a, const DisplayMesh& b) {
    const std::vector<glm::vec3> x = vertex_radiance(a, pipeline.solution().shown_radiosity);
    const std::vector<glm::vec3> y = vertex_radiance(b, pipeline.solution().shown_radiosity);
    EXPECT_EQ(x.size(), y.size());
    double largest = 0.0;
    for (std::size_t v = 0; v < std::min(x.size(), y.size()); ++v)
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, static_cast<double>(std::abs(x[v][c] - y[v][c])));
    return largest;
}

TEST(MaterialEdit, AColourEditRedrawsTheLightOnTheSameGeometry) {
    for (const char* subdivision : {"uniform", "hierarchical"}) {
        SCOPED_TRACE(subdivision);
        RadiosityPipeline pipeline(options_for("builtin:cornell", subdivision));
        pipeline.solve();
        const DisplayOptions options;
        DisplayMesh display = pipeline.build_display(options);
        const std::vector<glm::vec3> positions = display.positions;
        pipeline.edit_material("red", {0.2, 0.5, 0.7}, {0.0, 0.0, 0.0});
        pipeline.solve();
        EXPECT_FALSE(pipeline.redraw_display(display, options));  // no new geometry, no ray
        EXPECT_EQ(display.positions, positions);
        EXPECT_LT(largest_difference(pipeline, display, pipeline.build_display(options)), 1e-6);
        // The lamp's light changed: its light at the vertices is traced again.
        pipeline.edit_material("light", {0.78, 0.78, 0.78}, {8.0, 12.0, 16.0});
        pipeline.solve();
        EXPECT_TRUE(pipeline.redraw_display(display, options));
        EXPECT_LT(largest_difference(pipeline, display, pipeline.build_display(options)), 1e-6);
    }
}

// The sky and sun edited on a solved scene open to the outside: the light measured again on the same form
// factors, continued from the solution, is the fresh solve opened with that sky and sun; an empty value
// returns to the scene as opened, and a bad one changes nothing.
TEST(MaterialEdit, TheSkyAndSunChangedLiveReachTheFreshSolveOpenedWithThem) {
    PipelineOptions options = options_for("builtin:parallel", "uniform");
    options.scene.patch_size = 0.0;
    RadiosityPipeline edited(options);
    edited.solve();
    edited.edit_outside_light("0.2,0.3,0.4", "1,2,0.5,3");
    edited.solve();
    PipelineOptions lit = options;
    lit.scene.sky = "0.2,0.3,0.4";
    lit.scene.sun = "1,2,0.5,3";
    RadiosityPipeline fresh(lit);
    fresh.solve();
    EXPECT_EQ(edited.work().form_factor_passes, 1u);
    EXPECT_LT(relative_rms(edited, fresh), 1e-6);
    EXPECT_LT(relative_imbalance(edited), 0.005);
    EXPECT_GT(edited.energy_balance().outside.x, 0.0);

    EXPECT_THROW(edited.edit_outside_light("bright", ""), InputError);
    EXPECT_LT(relative_rms(edited, fresh), 1e-6);  // unchanged
    edited.edit_outside_light("", "");
    edited.solve();
    RadiosityPipeline unlit(options);
    unlit.solve();
    EXPECT_LT(relative_rms(edited, unlit), 1e-6);
    EXPECT_EQ(edited.energy_balance().outside.x, 0.0);
}

}  // namespace
}  // namespace rad
