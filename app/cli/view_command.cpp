// `radiosity [view] [SCENE]`: the interactive viewer, which is also what runs when no command is named.
// SCENE may be a saved solution (`solve --save`): shown at once, stepping continues from it.
#include <memory>

#include "cli/commands.hpp"
#include "cli/export_option.hpp"
#include "cli/number_checks.hpp"
#include "cli/solving_options.hpp"
#include "rad/io/saved_solution.hpp"
#include "viewer/viewer.hpp"
#include "viewer/viewer_options.hpp"

namespace rad {

namespace {

constexpr int kMaxWindowSide = 16384;

void add_viewer_options(CLI::App& command, ViewerOptions& options) {
    // The viewer steps bounces: jacobi unless asked otherwise (the panel switches methods).
    options.pipeline.solver.method = "jacobi";
    add_pipeline_options(command, options.pipeline);
    command.add_option("--width", options.width, "Window width in pixels")
        ->check(CLI::Range(1, kMaxWindowSide))
        ->capture_default_str();
    command.add_option("--height", options.height, "Window height in pixels")
        ->check(CLI::Range(1, kMaxWindowSide))
        ->capture_default_str();
    add_exposure_option(command, options.exposure,
                        "Show radiance x 2^EV; auto (the default), as render's PNGs: the EV that maps the "
                        "view's log-average luminance to 0.18 grey, metered as the view changes");
    command.add_option("--steps", options.steps, "Script: take N solver steps after the form factors")
        ->check(CLI::Range(0, 1000000));
    command.add_option("--screenshot", options.screenshot,
                       "Script: after --steps, save the window as this PNG");
    command.add_flag("--exit", options.exit, "Script: close the window after --steps (and --screenshot)");
    command
        .add_option("--idle", options.idle_seconds,
                    "Script: after --steps, stay open SECONDS untouched and print the frames drawn and the "
                    "CPU time used meanwhile")
        ->check(CLI::Range(0.0, 3600.0));
}

int run_view(ViewerOptions options, const CLI::App& command) {
    if (is_saved_solution_path(options.pipeline.scene.scene)) {
        refuse_solving_options(command, options.pipeline.scene.scene);
    }
    if (options.exit && options.steps < 0) options.steps = 0;  // --exit alone: show the emission, then close
    if (!options.screenshot.empty() && options.steps < 0) options.steps = 0;
    if (options.idle_seconds > 0.0 && options.steps < 0) options.steps = 0;
    Viewer viewer(options);
    return viewer.run();
}

}  // namespace

CommandRunner add_view_command(CLI::App& app) {
    auto view_options = std::make_shared<ViewerOptions>();
    auto bare_options = std::make_shared<ViewerOptions>();
    CLI::App* view =
        app.add_subcommand("view", "Show SCENE in a window and step its bounces (the default command)");
    add_viewer_options(*view, *view_options);
    add_viewer_options(app, *bare_options);
    return [view, view_options, bare_options]() -> int {
        return *view ? run_view(*view_options, *view) : run_view(*bare_options, *view->get_parent());
    };
}

}  // namespace rad
