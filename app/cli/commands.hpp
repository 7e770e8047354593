#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace rad {

// Each command registers itself as a subcommand of `app` and returns what to run if the user chose it.
// The runner returns the exit status; bad input throws InputError (exit 2).
using CommandRunner = std::function<int()>;

CommandRunner add_info_command(CLI::App& app);
CommandRunner add_solve_command(CLI::App& app);
CommandRunner add_render_command(CLI::App& app);
CommandRunner add_measure_command(CLI::App& app);
CommandRunner add_bench_command(CLI::App& app);
CommandRunner add_view_command(CLI::App& app);  // also the default when no command is named

}  // namespace rad
