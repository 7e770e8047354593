// The viewer worker's commands alone, without its thread: which runs next, and how a newer command replaces
// one that waits.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "viewer/worker_commands.hpp"

namespace rad {
namespace {

using Commands = WorkerCommands;

Commands::Rebuild rebuild(const std::string& scene, std::size_t steps = 0) {
    Commands::Rebuild rebuild;
    rebuild.options.scene.scene = scene;
    rebuild.steps = steps;
    return rebuild;
}

std::string scene_of(const Commands::Command& command) {
    return std::get<Commands::Rebuild>(command).options.scene.scene;
}

TEST(WorkerCommands, TheEarliestKindRunsFirstWhateverTheOrderAsked) {
    Commands commands;
    commands.set_can_step(true);
    commands.add_steps(1);
    commands.add(Commands::Write{"a.ply", 0.0});
    commands.add(Commands::OutsideLight{"5", ""});
    commands.add(Commands::MaterialEdit{"white", glm::dvec3(0.5), glm::dvec3(0.0)});
    commands.add(Commands::Reset{"jacobi", 1e-4, true});
    commands.add_steps(1);  // after the reset, which dropped the step asked before it
    commands.add(Commands::ColourModeSwitch{ColourMode::flat});
    commands.add(rebuild("builtin:cornell"));
    for (std::size_t kind = 0; kind < std::variant_size_v<Commands::Command>; ++kind) {
        ASSERT_TRUE(commands.has_next()) << "kind " << kind;
        EXPECT_EQ(commands.take_next().index(), kind);
        commands.end_job(true);
    }
    EXPECT_FALSE(commands.has_next());
}

TEST(WorkerCommands, TheLatestRebuildColourModeResetAndOutsideLightReplaceTheOneWaiting) {
    Commands commands;
    commands.add(rebuild("builtin:cube"));
    commands.add(rebuild("builtin:cornell"));
    commands.add(Commands::ColourModeSwitch{ColourMode::flat});
    commands.add(Commands::ColourModeSwitch{ColourMode::smooth});
    commands.add(Commands::Reset{"jacobi", 1e-3, true});
    commands.add(Commands::Reset{"gauss-seidel", 1e-4, true});
    commands.add(Commands::OutsideLight{"1", ""});
    commands.add(Commands::OutsideLight{"2", "0 0 -1 5"});
    EXPECT_EQ(scene_of(commands.take_next()), "builtin:cornell");
    commands.end_job(true);
    EXPECT_EQ(std::get<Commands::ColourModeSwitch>(commands.take_next()).mode, ColourMode::smooth);
    EXPECT_EQ(std::get<Commands::Reset>(commands.take_next()).method, "gauss-seidel");
    EXPECT_EQ(std::get<Commands::OutsideLight>(commands.take_next()).sky, "2");
    EXPECT_FALSE(commands.has_next());
}

TEST(WorkerCommands, AnEditReplacesTheWaitingEditOfItsMaterialAndWritesEachRunInTurn) {
    Commands commands;
    commands.add(Commands::MaterialEdit{"white", glm::dvec3(0.1), glm::dvec3(0.0)});
    commands.add(Commands::MaterialEdit{"red", glm::dvec3(0.2), glm::dvec3(0.0)});
    commands.add(Commands::MaterialEdit{"white", glm::dvec3(0.3), glm::dvec3(0.0)});
    commands.add(Commands::Write{"a.radiosity", 0.0});
    commands.add(Commands::Write{"a.radiosity", 0.0});
    commands.add(Commands::Write{"b.ply", 1.0});
    const auto edit = [&] { return std::get<Commands::MaterialEdit>(commands.take_next()); };
    EXPECT_EQ(edit().name, "red");
    const Commands::MaterialEdit white = edit();
    EXPECT_EQ(white.name, "white");
    EXPECT_EQ(white.reflectance, glm::dvec3(0.3));
    for (const char* path : {"a.radiosity", "a.radiosity", "b.ply"})
        EXPECT_EQ(std::get<Commands::Write>(commands.take_next()).path, path);
    EXPECT_FALSE(commands.has_next());
}

// Steps asked for before the solver exists wait for it; a run steps without a count until it is paused.
TEST(WorkerCommands, StepsAddUpAndWaitForASolverThatCanTakeThem) {
    Commands commands;
    commands.add_steps(2);
    commands.add(Commands::Step{});
    EXPECT_EQ(commands.steps(), 3u);
    EXPECT_FALSE(commands.has_next());
    commands.set_can_step(true);
    for (std::size_t left = 3; left > 0; --left) {
        ASSERT_TRUE(commands.has_next());
        EXPECT_TRUE(std::holds_alternative<Commands::Step>(commands.take_next()));
        EXPECT_EQ(commands.steps(), left - 1);
    }
    EXPECT_FALSE(commands.has_next());
    commands.set_running(true);
    EXPECT_TRUE(std::holds_alternative<Commands::Step>(commands.take_next()));
    EXPECT_TRUE(commands.has_next());
    commands.set_can_step(false);  // the solver finished
    EXPECT_FALSE(commands.has_next());
}

TEST(WorkerCommands, AResetOrAStopDropsTheStepsAskedAndPausesTheRun) {
    Commands commands;
    commands.set_can_step(true);
    commands.add_steps(5);
    commands.set_running(true);
    commands.add(Commands::Reset{"jacobi", 1e-4, true});
    EXPECT_EQ(commands.steps(), 0u);
    EXPECT_FALSE(commands.running());
    EXPECT_TRUE(std::holds_alternative<Commands::Reset>(commands.take_next()));
    EXPECT_FALSE(commands.has_next());
    commands.add_steps(5);
    commands.set_running(true);
    commands.stop_stepping();
    EXPECT_EQ(commands.steps(), 0u);
    EXPECT_FALSE(commands.running());
    EXPECT_FALSE(commands.has_next());
}

// A rebuild cut short by a newer one whose file does not open waits again, once.
TEST(WorkerCommands, ARebuildCutShortByAFileThatDoesNotOpenWaitsAgain) {
    Commands commands;
    commands.add(rebuild("builtin:cornell", 1));
    EXPECT_EQ(scene_of(commands.take_next()), "builtin:cornell");
    commands.add(rebuild("/nonexistent/scene.obj"));
    commands.end_job(false);  // cancelled by the newer one
    EXPECT_EQ(scene_of(commands.take_next()), "/nonexistent/scene.obj");
    EXPECT_TRUE(commands.restart_interrupted());
    commands.end_job(true);
    const Commands::Command restarted = commands.take_next();
    EXPECT_EQ(scene_of(restarted), "builtin:cornell");
    EXPECT_EQ(std::get<Commands::Rebuild>(restarted).steps, 1u);
    EXPECT_FALSE(commands.restart_interrupted());  // it cut nothing short
    commands.end_job(true);
    EXPECT_FALSE(commands.has_next());
}

TEST(WorkerCommands, NoRebuildWaitsAgainOnceTheNewerOneOpensOrANewerStillWaits) {
    Commands commands;
    commands.add(rebuild("builtin:cornell"));
    commands.take_next();
    commands.add(rebuild("builtin:cube"));
    commands.end_job(false);
    commands.take_next();
    commands.opened();
    EXPECT_FALSE(commands.restart_interrupted());
    commands.end_job(true);

    commands.add(rebuild("builtin:cornell"));
    commands.take_next();
    commands.add(rebuild("/nonexistent/a.obj"));
    commands.end_job(false);
    commands.take_next();
    commands.add(rebuild("builtin:parallel"));  // asked while the first failed file loads
    EXPECT_FALSE(commands.restart_interrupted());
    commands.end_job(true);
    EXPECT_EQ(scene_of(commands.take_next()), "builtin:parallel");
    commands.end_job(true);
    EXPECT_FALSE(commands.has_next());
}

// The rebuild that ran to its end need not run again when a later file does not open.
TEST(WorkerCommands, ACompletedRebuildIsNotRestarted) {
    Commands commands;
    commands.add(rebuild("builtin:cornell"));
    commands.take_next();
    commands.end_job(true);
    commands.add(rebuild("/nonexistent/a.obj"));
    commands.take_next();
    EXPECT_FALSE(commands.restart_interrupted());
}

}  // namespace
}  // namespace rad
