// The viewer's background worker, without a window: it takes the steps asked for, keeps each bounce
// alone (paths L D^k E), runs to convergence, switches smooth and flat colours, resets to the emission
// without recomputing form factors, cancels long work promptly, and opens saved solutions (FILE.radiosity)
// through the same request as scenes.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "pipeline/radiosity_pipeline.hpp"
#include "rad/io/saved_solution.hpp"
#include "test_support.hpp"
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
    // A gathered vertex shows the previous step's light reflected once (stepped_vertex_radiance), a
    // pipeline's own view the latest step's, and the bounce views show the patches; these tests compare one
    // with the other, bounce by bounce (the gather's own test is AGatheredVertexShowsTheBouncesOfItsStep).
    options.display.final_gather = FinalGather::off;
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

// A gathered vertex reflects once what it gathers: over Jacobi step k's radiosity it would show k + 1
// bounces beside vertices that show k (a bright halo by the walls and blocks while the light builds up).
// The viewer gathers the step before: at step 3 a vertex with a row shows what a pipeline's view shows after
// 2 steps (its emission, its direct light and ρ Σ share (B_2 − E): three bounces), and a vertex without one
// the patches' reconstruction after 3.
TEST(ViewerWorker, AGatheredVertexShowsTheBouncesOfItsStep) {
    PipelineOptions options = cornell(100.0);
    options.display.final_gather = FinalGather::on;
    SolverWorker worker(options);
    worker.request_steps(3);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.error.empty()) << snapshot.error;
    ASSERT_TRUE(snapshot.radiance);
    EXPECT_EQ(snapshot.radiance->step, 3u);
    RadiosityPipeline pipeline(options);
    pipeline.prepare();
    const GatherTable& rows = pipeline.display().traced.gather;
    ASSERT_FALSE(rows.empty());
    const std::vector<glm::vec3> two = radiance_after(options, 2), three = radiance_after(options, 3);
    const std::vector<glm::vec3>& shown = snapshot.radiance->cumulative;
    ASSERT_EQ(shown.size(), two.size());
    std::size_t gathered = 0, differ = 0;
    for (std::size_t v = 0; v < shown.size(); ++v) {
        const bool row = rows.row_begin[v] < rows.row_begin[v + 1];
        const glm::vec3 expected = row ? two[v] : three[v];
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(shown[v][c], expected[c], 1e-5f * (1.0f + std::abs(expected[c]))) << "vertex " << v;
        gathered += row ? 1 : 0;
        differ += row && std::abs(two[v].y - three[v].y) > 1e-3f * three[v].y ? 1 : 0;
    }
    EXPECT_GT(gathered, shown.size() / 2);
    EXPECT_GT(differ, gathered / 2);  // the two views differ: the test can tell them apart
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
    // Fine enough that the form factors take many seconds (minutes under sanitizers); uniform, which
    // --subdivision auto would not pick for so many patches.
    PipelineOptions options = cornell(12.0);
    options.subdivision.method = "uniform";
    SolverWorker worker(options);
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
    // The view is not black: the preview of the emitters' direct light, traced before the form factors,
    // stays. With the emission alone only the lamp's vertices (under 2 %) would be lit; the floor, the walls
    // and the blocks see the lamp.
    ASSERT_TRUE(snapshot.radiance && snapshot.geometry);
    ASSERT_EQ(snapshot.radiance->cumulative.size(), snapshot.geometry->positions.size());
    EXPECT_EQ(snapshot.radiance->step, 0u);
    std::size_t lit = 0;
    for (const glm::vec3& l : snapshot.radiance->cumulative) {
        ASSERT_TRUE(std::isfinite(l.r + l.g + l.b));
        if (l.r + l.g + l.b > 0.0f) ++lit;
    }
    EXPECT_GT(lit, snapshot.radiance->cumulative.size() / 2);
}

// Waits until the worker runs `stage`; false if it does not within the limit.
bool wait_for_stage(const SolverWorker& worker, const std::string& stage, std::chrono::seconds limit) {
    const auto give_up = Clock::now() + limit;
    while (!(worker.progress() && worker.progress()->stage() == stage)) {
        if (Clock::now() > give_up) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

TEST(ViewerWorker, ReMeshingKeepsTheSolutionShownUntilTheNewOneIsReadyAndACancelKeepsIt) {
    SolverWorker worker(cornell(100.0));
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot solved = worker.snapshot();
    ASSERT_TRUE(solved.radiance && solved.geometry);
    ASSERT_EQ(solved.radiance->step, 2u);

    PipelineOptions finer = cornell(12.0);
    finer.subdivision.method = "uniform";
    worker.request_rebuild(finer);
    ASSERT_TRUE(wait_for_stage(worker, "form factors", std::chrono::seconds(120)));
    const SolverSnapshot during = worker.snapshot();
    EXPECT_EQ(during.geometry, solved.geometry);
    EXPECT_EQ(during.radiance, solved.radiance);
    EXPECT_EQ(during.statistics.patches, solved.statistics.patches);

    worker.cancel();
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(30)));
    const SolverSnapshot after = worker.snapshot();
    EXPECT_NE(after.error.find("cancelled"), std::string::npos) << after.error;
    EXPECT_EQ(after.geometry, solved.geometry);
    ASSERT_TRUE(after.radiance);
    EXPECT_EQ(after.radiance->step, 2u);
    EXPECT_TRUE(after.statistics.prepared);
    // The solution shown can still be stepped.
    worker.request_steps(1);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    ASSERT_TRUE(worker.snapshot().radiance);
    EXPECT_EQ(worker.snapshot().radiance->step, 3u);
}

// A re-mesh that runs to its end shows the new mesh: the geometry and the colours the new patches give, one
// colour per vertex, and it steps on.
TEST(ViewerWorker, AFinishedReMeshShowsTheNewMeshAndStepsOn) {
    SolverWorker worker(cornell(100.0));
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot coarse = worker.snapshot();
    worker.request_rebuild(cornell(70.0));
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot fine = worker.snapshot();
    EXPECT_TRUE(fine.error.empty()) << fine.error;
    ASSERT_TRUE(fine.geometry && fine.radiance && coarse.geometry);
    EXPECT_GT(fine.statistics.patches, coarse.statistics.patches);
    EXPECT_GT(fine.geometry->positions.size(), coarse.geometry->positions.size());
    EXPECT_EQ(fine.radiance->cumulative.size(), fine.geometry->positions.size());
    EXPECT_EQ(fine.radiance->step, 2u);
    expect_near(fine.radiance->cumulative, radiance_after(cornell(70.0), 2));
}

// The step asked for with a scene (the panel opens scenes at their first bounce) is taken once the scene has
// opened: a file that cannot be opened leaves the scene shown as it was, not a step further.
TEST(ViewerWorker, TheStepsAskedWithASceneThatDoesNotOpenAreNotTaken) {
    SolverWorker worker(cornell(100.0));
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    PipelineOptions missing = cornell(100.0);
    missing.scene.scene = "/nonexistent/scene.obj";
    worker.request_rebuild(missing, 1);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(60)));
    EXPECT_TRUE(worker.snapshot().bad_input);
    ASSERT_TRUE(worker.snapshot().radiance);
    EXPECT_EQ(worker.snapshot().radiance->step, 2u);
    worker.request_rebuild(cornell(70.0), 1);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    ASSERT_TRUE(worker.snapshot().radiance);
    EXPECT_EQ(worker.snapshot().radiance->step, 1u);
}

TEST(ViewerWorker, AFileThatCannotBeOpenedStartsTheInterruptedFormFactorsAgain) {
    PipelineOptions options = cornell(12.0);
    options.subdivision.method = "uniform";
    SolverWorker worker(options);
    ASSERT_TRUE(wait_for_stage(worker, "form factors", std::chrono::seconds(120)));
    PipelineOptions missing = options;
    missing.scene.scene = "/nonexistent/dropped.obj";
    worker.request_rebuild(missing);
    // The failed load reports itself and queues the cut-short work again.
    const auto give_up = Clock::now() + std::chrono::seconds(60);
    while (worker.snapshot().error.find("dropped.obj") == std::string::npos && Clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_TRUE(worker.snapshot().bad_input);
    EXPECT_TRUE(wait_for_stage(worker, "form factors", std::chrono::seconds(120)));
    EXPECT_EQ(worker.snapshot().statistics.scene, "builtin:cornell");
    // The message stays while the restarted work runs.
    EXPECT_NE(worker.snapshot().error.find("dropped.obj"), std::string::npos) << worker.snapshot().error;
    worker.cancel();
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(30)));
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

// A Cornell box solved by 3 Jacobi steps, far from converged, so that stepping can continue.
PipelineOptions unfinished_cornell() {
    PipelineOptions options = cornell(100.0);
    options.solver.method = "jacobi";
    options.solver.tolerance = 1e-12;
    return options;
}

constexpr std::size_t kSavedSteps = 3;

SavedSolution solved(const PipelineOptions& options) {
    RadiosityPipeline pipeline(options);
    pipeline.prepare();
    for (std::size_t i = 0; i < kSavedSteps; ++i) pipeline.step();
    return pipeline.saved_solution();
}

std::string write_saved(const test::TempDir& dir, const std::string& name, const SavedSolution& saved) {
    const std::string path = (dir.path() / name).string();
    write_saved_solution(path, saved);
    return path;
}

PipelineOptions opening(PipelineOptions options, const std::string& path) {
    options.scene.scene = path;
    return options;
}

// The panel's Open (and a dropped file) sends the scene field through request_rebuild: a saved solution is
// shown as saved, its transport rebuilt once behind it, and stepping continues from it.
TEST(ViewerWorker, OpensASavedSolutionAndContinuesSteppingFromIt) {
    const PipelineOptions options = unfinished_cornell();
    test::TempDir dir;
    const std::string path = write_saved(dir, "cornell.radiosity", solved(options));
    PipelineOptions cube = cornell(0.0);
    cube.scene.scene = "builtin:cube";
    SolverWorker worker(cube);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));

    worker.request_rebuild(opening(cube, path));
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.error.empty()) << snapshot.error;
    ASSERT_TRUE(snapshot.geometry && snapshot.radiance);
    EXPECT_EQ(snapshot.statistics.scene, path);
    EXPECT_EQ(snapshot.statistics.patches, RadiosityPipeline(options).patches().size());
    EXPECT_EQ(snapshot.radiance->step, kSavedSteps);  // the saved count, not 0 from a fresh solver
    expect_near(snapshot.radiance->cumulative, radiance_after(options, kSavedSteps));
    EXPECT_TRUE(snapshot.statistics.prepared);
    EXPECT_EQ(snapshot.statistics.form_factor_passes, 1u);
    // What the panel's controls take and "Re-mesh and recompute" starts from: the saved scene and settings.
    ASSERT_TRUE(snapshot.statistics.saved_options);
    const PipelineOptions& saved = *snapshot.statistics.saved_options;
    EXPECT_EQ(saved.scene.scene, "builtin:cornell");
    EXPECT_EQ(saved.scene.patch_size, 100.0);
    EXPECT_EQ(saved.subdivision.method, "uniform");
    EXPECT_EQ(saved.solver.method, "jacobi");
    EXPECT_EQ(saved.solver.tolerance, 1e-12);
    EXPECT_TRUE(snapshot.statistics.remesh_unavailable.empty()) << snapshot.statistics.remesh_unavailable;
    const std::uint64_t version = snapshot.geometry->scene_version;

    worker.request_steps(1);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.radiance);
    EXPECT_EQ(snapshot.radiance->step, kSavedSteps + 1);
    expect_near(snapshot.radiance->cumulative, radiance_after(options, kSavedSteps + 1));
    ASSERT_TRUE(snapshot.radiance->bounce(kSavedSteps + 1));
    EXPECT_EQ(snapshot.statistics.form_factor_passes, 1u);

    // Re-mesh: the saved scene solved again from the emission, in the same view (the same scene).
    worker.request_rebuild(saved);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.error.empty()) << snapshot.error;
    ASSERT_TRUE(snapshot.geometry && snapshot.radiance);
    EXPECT_EQ(snapshot.statistics.scene, "builtin:cornell");
    EXPECT_FALSE(snapshot.statistics.saved_options);
    EXPECT_EQ(snapshot.radiance->step, 0u);
    expect_near(snapshot.radiance->cumulative, radiance_after(options, 0));
    EXPECT_EQ(snapshot.geometry->scene_version, version);
}

// The saved radiosity is on screen before any form factor is computed. Its settings here name a fine mesh,
// so rebuilding the transport takes long enough to look while it runs (and ends in an error: the rebuilt
// elements are not the saved ones).
TEST(ViewerWorker, ShowsASavedSolutionBeforeAnyFormFactorPass) {
    const PipelineOptions options = unfinished_cornell();
    SavedSolution saved = solved(options);
    saved.solution.settings.patch_size = 12.0;
    test::TempDir dir;
    SolverWorker worker(opening(options, write_saved(dir, "slow.radiosity", saved)));
    const auto give_up = Clock::now() + std::chrono::seconds(120);
    while (!(worker.progress() && worker.progress()->stage() == "form factors") && Clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    ASSERT_TRUE(worker.progress() && worker.progress()->stage() == "form factors");
    SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.geometry && snapshot.radiance);
    EXPECT_EQ(snapshot.radiance->step, kSavedSteps);
    expect_near(snapshot.radiance->cumulative, radiance_after(options, kSavedSteps));
    EXPECT_FALSE(snapshot.statistics.prepared);
    EXPECT_EQ(snapshot.statistics.form_factor_passes, 0u);
    EXPECT_EQ(snapshot.statistics.patches, saved.solution.size());

    worker.cancel();
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(30)));
    snapshot = worker.snapshot();
    EXPECT_NE(snapshot.error.find("cancelled"), std::string::npos) << snapshot.error;
    ASSERT_TRUE(snapshot.radiance);  // still the saved solution
    EXPECT_EQ(snapshot.radiance->step, kSavedSteps);
}

// Its transport rebuilt with other elements (a file from another version, say): the error is shown beside
// the saved solution, which stays, and nothing reads the solver that was never made.
TEST(ViewerWorker, ASavedSolutionWhoseTransportDiffersStaysShownWithTheError) {
    const PipelineOptions options = unfinished_cornell();
    SavedSolution saved = solved(options);
    saved.solution.settings.patch_size = 90.0;  // 7 patches an edge, not 6
    test::TempDir dir;
    SolverWorker worker(opening(options, write_saved(dir, "other.radiosity", saved)));
    worker.request_steps(1);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot snapshot = worker.snapshot();
    EXPECT_NE(snapshot.error.find("elements, not the saved"), std::string::npos) << snapshot.error;
    EXPECT_TRUE(snapshot.bad_input);
    EXPECT_FALSE(snapshot.statistics.prepared);
    ASSERT_TRUE(snapshot.radiance);
    EXPECT_EQ(snapshot.radiance->step, kSavedSteps);  // the step asked for was not taken
    expect_near(snapshot.radiance->cumulative, radiance_after(options, kSavedSteps));
}

// The saved file holds its scene, so it opens and steps; but re-meshing loads the scene file, which is gone.
TEST(ViewerWorker, ASavedSolutionWhoseSceneFileIsGoneCannotBeRemeshed) {
    const PipelineOptions options = unfinished_cornell();
    SavedSolution saved = solved(options);
    test::TempDir dir;
    const std::string moved = (dir.path() / "moved.obj").string();
    saved.solution.settings.scene_source = moved;
    SolverWorker worker(opening(options, write_saved(dir, "moved.radiosity", saved)));
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot snapshot = worker.snapshot();
    ASSERT_TRUE(snapshot.error.empty()) << snapshot.error;
    EXPECT_TRUE(snapshot.statistics.prepared);
    ASSERT_TRUE(snapshot.statistics.saved_options);
    EXPECT_EQ(snapshot.statistics.saved_options->scene.scene, moved);
    EXPECT_NE(snapshot.statistics.remesh_unavailable.find(moved), std::string::npos)
        << snapshot.statistics.remesh_unavailable;
}

// A damaged or foreign .radiosity file opened over a scene: the one-line error, and the scene as it was,
// still stepping.
TEST(ViewerWorker, ABadSavedSolutionLeavesThePreviousSceneShown) {
    const PipelineOptions options = unfinished_cornell();
    test::TempDir dir;
    std::string damaged = encode_saved_solution(solved(options));
    damaged[kSavedSolutionHeaderBytes + damaged.size() / 2] ^= 0x40;  // the checksum no longer matches
    const std::vector<std::string> paths = {dir.write("damaged.radiosity", damaged),
                                            dir.write("foreign.radiosity", "solid cube\nendsolid\n"),
                                            (dir.path() / "missing.radiosity").string()};
    SolverWorker worker(options);
    worker.request_steps(2);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot before = worker.snapshot();
    ASSERT_TRUE(before.error.empty() && before.geometry && before.radiance) << before.error;

    for (const std::string& path : paths) {
        worker.request_rebuild(opening(options, path));
        ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(30)));
        const SolverSnapshot after = worker.snapshot();
        EXPECT_TRUE(after.bad_input) << path;
        EXPECT_NE(after.error.find(path), std::string::npos) << after.error;
        EXPECT_EQ(after.error.find('\n'), std::string::npos) << after.error;
        EXPECT_EQ(after.geometry, before.geometry) << path;
        EXPECT_EQ(after.radiance, before.radiance) << path;
        EXPECT_EQ(after.statistics.scene, "builtin:cornell");
        EXPECT_FALSE(after.statistics.saved_options);
    }
    worker.request_steps(1);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot stepped = worker.snapshot();
    ASSERT_TRUE(stepped.radiance);
    EXPECT_EQ(stepped.radiance->step, 3u);
    expect_near(stepped.radiance->cumulative, radiance_after(options, 3));
}

// Files written from the window: the solution (read back at its step), the mesh with its colours, and a
// name of no known kind refused with the file named; nothing of the solution changes.
TEST(ViewerWorker, SavesTheSolutionAndExportsTheMeshShown) {
    const test::TempDir folder;
    SolverWorker worker(cornell(100.0));
    worker.request_steps(3);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const std::string saved = (folder.path() / "cornell.radiosity").string();
    const std::string mesh = (folder.path() / "cornell.ply").string();
    worker.request_write(saved, 0.0);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(60)));
    EXPECT_EQ(worker.snapshot().written, "wrote " + saved);
    EXPECT_EQ(read_saved_solution(saved).solution.report.steps, 3u);
    worker.request_write(mesh, 0.0);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(60)));
    EXPECT_EQ(worker.snapshot().written, "wrote " + mesh);
    EXPECT_GT(std::filesystem::file_size(mesh), 1000u);
    const std::string unknown = (folder.path() / "cornell.txt").string();
    worker.request_write(unknown, 0.0);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(60)));
    EXPECT_NE(worker.snapshot().error.find("cornell.txt"), std::string::npos) << worker.snapshot().error;
    EXPECT_FALSE(std::filesystem::exists(unknown));
    ASSERT_TRUE(worker.snapshot().radiance);
    EXPECT_EQ(worker.snapshot().radiance->step, 3u);
}

// A sky set from the panel lights the scene shown without a new form-factor pass, and the solver runs on
// by itself until it converges; a bad value is reported as bad input and changes nothing.
TEST(ViewerWorker, ASkySetLiveLightsTheSceneWithTheSameFormFactors) {
    PipelineOptions options = cornell(0.0);
    options.scene.scene = "builtin:parallel";
    SolverWorker worker(options);
    worker.request_steps(30);
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const auto total = [](const SolverSnapshot& snapshot) {
        double sum = 0.0;
        for (const glm::vec3& l : snapshot.radiance->cumulative) sum += l.r + l.g + l.b;
        return sum;
    };
    const SolverSnapshot before = worker.snapshot();
    ASSERT_TRUE(before.radiance);
    worker.request_outside_light("bright", "");
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(60)));
    EXPECT_TRUE(worker.snapshot().bad_input);
    EXPECT_NE(worker.snapshot().error.find("--sky"), std::string::npos) << worker.snapshot().error;
    worker.request_outside_light("5", "");
    ASSERT_TRUE(wait_until_idle(worker, std::chrono::seconds(120)));
    const SolverSnapshot after = worker.snapshot();
    ASSERT_TRUE(after.radiance);
    EXPECT_TRUE(after.error.empty()) << after.error;
    EXPECT_EQ(after.statistics.form_factor_passes, 1u);
    EXPECT_EQ(after.statistics.status, SolverStatus::converged);
    EXPECT_GT(total(after), total(before) * 1.5);
}

}  // namespace
}  // namespace rad
