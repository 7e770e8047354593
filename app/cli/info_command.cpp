#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/scene_summary.hpp"
#include "cli/solving_options.hpp"
#include "pipeline/scene_options.hpp"

namespace rad {

CommandRunner add_info_command(CLI::App& app) {
    auto options = std::make_shared<SceneOptions>();
    CLI::App* info =
        app.add_subcommand("info", "Print SCENE's surfaces, materials, patch count, area and bounds");
    add_scene_options(*info, *options);
    return [info, options]() -> int {
        if (!*info) return -1;
        print_scene_summary(std::cout, load_and_mesh(*options));
        return 0;
    };
}

}  // namespace rad
