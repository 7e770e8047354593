#include <iostream>
#include <memory>

#include "commands.hpp"
#include "scene_options.hpp"
#include "scene_summary.hpp"

namespace rad {

// Until the interactive viewer lands, `view` (and the bare `radiosity [SCENE]`) prints the scene summary.
CommandRunner add_view_command(CLI::App& app) {
    auto view_options = std::make_shared<SceneOptions>();
    auto bare_options = std::make_shared<SceneOptions>();
    CLI::App* view = app.add_subcommand("view", "Show SCENE (the default command; for now it prints the summary)");
    add_scene_options(*view, *view_options);
    add_scene_options(app, *bare_options);
    return [view, view_options, bare_options]() -> int {
        print_scene_summary(std::cout, load_and_mesh(*view ? *view_options : *bare_options));
        return 0;
    };
}

}  // namespace rad
