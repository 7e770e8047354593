#include "cli/command_line.hpp"

namespace rad {

CommandLine::CommandLine() {
    app_.require_subcommand(0, 1);
    // The view command, the default, comes last: it runs when no other command claims the arguments.
    commands_ = {
        add_info_command(app_),    add_solve_command(app_), add_render_command(app_),
        add_measure_command(app_), add_bench_command(app_), add_view_command(app_),
    };
}

int CommandLine::run_chosen_command() const {
    for (const auto& command : commands_) {
        if (const int status = command(); status >= 0) return status;
    }
    return 1;
}

}  // namespace rad
