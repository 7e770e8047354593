#pragma once

#include <CLI/CLI.hpp>
#include <vector>

#include "cli/commands.hpp"

namespace rad {

// The radiosity command line: the CLI11 app with every command registered, and what to run once it has
// parsed. Parsing only stores options (and --threads limits TBB); nothing runs until run_chosen_command.
class CommandLine {
  public:
    CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    CLI::App& app() { return app_; }
    // Runs the command the parsed arguments chose (the viewer when none is named); returns its exit status.
    int run_chosen_command() const;

  private:
    CLI::App app_{"radiosity: diffuse global illumination by the radiosity method"};
    std::vector<CommandRunner> commands_;  // in the order they are tried
};

}  // namespace rad
