// The viewer's background worker, without a window: it takes the steps asked for, keeps each bounce
// alone (paths L D^k E), runs to convergence, switches smooth and flat colours, resets to the emission
// without recomputing form factors, and cancels long work promptly.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "pipeline/radiosity_pipeline.hpp"
#include "viewer/solver_worker.hpp"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;

PipelineOptions cornell(double patch_size) {
    PipelineOptions options;
    options.scene.scene = "builtin:cornell";
    options.scene.patch_size = patch_size;
    // The area-weighted average is linear in B, so the radiance of one bounce alone is the difference of
    // two cumulative ones; linear reconstruction clamps negative extrapolations to 0, which is not.
    options.display.reconstruction = Reconstruction::average;
    return options;
}

// Polls the way the render thread does, once a millisecond; false if the worker is still busy at the limit.
bool wait_until_idle(const SolverWorker& worker, std::chrono::seconds limit) {
    const auto give_up = Clock::now() + limit;
    while (worker.busy()) {
        if (Clock::now() > give_up) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

// The per-vertex radiance a pipeline of the same options shows after `steps` Jacobi steps.
std::vector<glm::vec3> radiance_after(const PipelineOptions& options, std::size_t steps) {
    RadiosityPipeline pipeline(options);
    pipeline.prepare();
    for (std::size_t i = 0; i < steps; ++i) pipeline.step();
    return pipeline.vertex_radiance();
}

void expect_near(const std::vector<glm::vec3>& actual, const std::vector<glm::vec3>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t v = 0; v < actual.size(); ++v) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_NEAR(actual[v][c], expected[v][c], 1e-5f * (1.0f + std::abs(expected[v][c])))
                << "vertex " << v;
        }
    }
}

TEST(ViewerWorker, TakesTheStepsAskedForAndKeepsEachBounceAlone) {
    const PipelineOptions options = cornell(100.0);
    SolverWorker worker(options);
    worker.request_steps(3);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.error.empty()) << snapshot.error;
    ASSERT_TRUE(snapshot.geometry && snapshot.radiance);
    EXPECT_EQ(snapshot.radiance->step, 3u);
    EXPECT_EQ(snapshot.statistics.log_residual.size(), 3u);
    EXPECT_EQ(snapshot.radiance->cumulative.size(), snapshot.geometry->positions.size());

    // Jacobi step k holds the paths of up to k bounces, so bounce k alone (paths L D^k E) is B_k − B_{k−1}.
    std::vector<glm::vec3> before(snapshot.geometry->positions.size(), glm::vec3(0.0f));
    for (std::size_t k = 0; k <= 3; ++k) {
        const std::vector<glm::vec3> after = radiance_after(options, k);
        if (k == 3) expect_near(snapshot.radiance->cumulative, after);
        std::vector<glm::vec3> alone(after.size());
        for (std::size_t v = 0; v < after.size(); ++v) alone[v] = after[v] - before[v];
        ASSERT_TRUE(snapshot.radiance->bounce(k)) << "bounce " << k;
        expect_near(*snapshot.radiance->bounce(k), alone);
        before = after;
    }
    EXPECT_FALSE(snapshot.radiance->bounce(4));
}

// Hierarchical radiosity (the panel's subdivision choice): the geometry the render thread gets is the
// leaves', not the base patches', and stepping shows what a pipeline of the same options shows.
TEST(ViewerWorker, HierarchicalLeavesAreWhatIsDrawnAndStepped) {
    PipelineOptions options = cornell(0.0);
    options.subdivision.method = "hierarchical";
    SolverWorker worker(options);
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(300)));
    const SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.error.empty()) << snapshot.error;
    ASSERT_TRUE(snapshot.geometry && snapshot.radiance);
    EXPECT_EQ(snapshot.statistics.subdivision, "hierarchical");
    EXPECT_GT(snapshot.statistics.patches, 197u);  // more leaves than base patches
    // The panel's "N links" (it showed 0: the hierarchy has no form-factor matrix).
    EXPECT_EQ(snapshot.statistics.interaction_name, "links");
    RadiosityPipeline pipeline(options);
    pipeline.prepare();
    EXPECT_EQ(snapshot.statistics.interactions, pipeline.transport().report().interactions);
    EXPECT_GT(snapshot.statistics.interactions, snapshot.statistics.patches);
    EXPECT_EQ(snapshot.radiance->step, 2u);
    expect_near(snapshot.radiance->cumulative, radiance_after(options, 2));
}

TEST(ViewerWorker, ResetReturnsToTheEmissionWithoutRecomputingFormFactors) {
    const PipelineOptions options = cornell(100.0);
    SolverWorker worker(options);
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    worker.request_reset("gauss-seidel", 1e-4);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));

    const SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.radiance);
    EXPECT_EQ(snapshot.radiance->step, 0u);
    EXPECT_EQ(snapshot.statistics.form_factor_passes, 1u);
    EXPECT_EQ(snapshot.statistics.method, SolverMethod::gauss_seidel);
    EXPECT_TRUE(snapshot.statistics.log_residual.empty());
    expect_near(snapshot.radiance->cumulative, radiance_after(options, 0));  // B = E
    ASSERT_TRUE(snapshot.radiance->bounce(0));
    expect_near(*snapshot.radiance->bounce(0), radiance_after(options, 0));  // step 0's light is the emission
    EXPECT_FALSE(snapshot.radiance->bounce(1));  // the steps before the reset are forgotten
}

TEST(ViewerWorker, RunStepsUntilTheSolverConverges) {
    PipelineOptions options = cornell(100.0);
    options.solver.tolerance = 1e-3;
    SolverWorker worker(options);
    worker.set_running(true);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot snapshot = worker.snapshot();
    EXPECT_EQ(snapshot.statistics.status, SolverStatus::converged) << snapshot.statistics.status_message;
    EXPECT_FALSE(worker.running());  // a finished solver pauses the run
    ASSERT_TRUE(snapshot.radiance);
    EXPECT_EQ(snapshot.statistics.log_residual.size(), snapshot.radiance->step);
    EXPECT_LE(snapshot.statistics.log_residual.back(), -3.0f);
}

TEST(ViewerWorker, FlatColoursChangeTheGeometryButNotTheSolution) {
    SolverWorker worker(cornell(100.0));
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot smooth = worker.snapshot();
    worker.request_colour_mode(ColourMode::flat);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot flat = worker.snapshot();

    ASSERT_TRUE(smooth.geometry && flat.geometry && flat.radiance);
    EXPECT_NE(flat.geometry, smooth.geometry);
    EXPECT_GT(flat.geometry->positions.size(),
              smooth.geometry->positions.size());  // each patch its own corners
    EXPECT_EQ(flat.radiance->step, 2u);
    EXPECT_EQ(flat.statistics.form_factor_passes, 1u);
    EXPECT_EQ(flat.radiance->cumulative.size(), flat.geometry->positions.size());
    for (std::size_t k = 0; k <= 2; ++k) {
        ASSERT_TRUE(flat.radiance->bounce(k));
        EXPECT_EQ(flat.radiance->bounce(k)->size(), flat.geometry->positions.size()) << "bounce " << k;
    }
}

TEST(ViewerWorker, CancelStopsTheFormFactorsPromptly) {
    // Fine enough that the form factors take many seconds (minutes under sanitizers).
    SolverWorker worker(cornell(12.0));
    const auto give_up = Clock::now() + std::chrono::seconds(120);
    while (!(worker.progress() && worker.progress()->stage() == "form factors") && Clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    const std::shared_ptr<const Progress> progress = worker.progress();
    ASSERT_TRUE(progress && progress->stage() == "form factors") << "the form factors never started";
    const auto asked = Clock::now();
    worker.cancel();
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(30)));
    const double seconds = std::chrono::duration<double>(Clock::now() - asked).count();
    EXPECT_LT(seconds, 2.0);
    const SolverSnapshot snapshot = worker.snapshot();
    EXPECT_NE(snapshot.error.find("cancelled"), std::string::npos) << snapshot.error;
    EXPECT_FALSE(snapshot.statistics.prepared);
    EXPECT_FALSE(snapshot.radiance);
}

TEST(ViewerWorker, ABadSceneIsReportedAsBadInput) {
    PipelineOptions options = cornell(0.0);
    options.scene.scene = "/nonexistent/scene.obj";
    SolverWorker worker(options);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(30)));
    const SolverSnapshot snapshot = worker.snapshot();
    EXPECT_TRUE(snapshot.bad_input);
    EXPECT_NE(snapshot.error.find("/nonexistent/scene.obj"), std::string::npos) << snapshot.error;
}

}  // namespace
}  // namespace rad
