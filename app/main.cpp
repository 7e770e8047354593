// radiosity: computes diffuse global illumination once and shows it from any viewpoint.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "commands.hpp"
#include "rad/error.hpp"

namespace {

int run(int argc, char** argv) {
    CLI::App app{"radiosity: diffuse global illumination by the radiosity method"};
    app.require_subcommand(0, 1);
    // Commands in the order they are tried; the view command, the default, runs when none other claims.
    const std::vector<rad::CommandRunner> commands = {
        rad::add_info_command(app),  rad::add_solve_command(app), rad::add_render_command(app),
        rad::add_bench_command(app), rad::add_view_command(app),
    };
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "radiosity: error: " << e.what() << " (see radiosity --help)\n";
        return 2;
    }
    for (const auto& command : commands) {
        if (const int status = command(); status >= 0) return status;
    }
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const rad::InputError& e) {
        std::cerr << "radiosity: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "radiosity: failed: " << e.what() << '\n';
        return 1;
    }
}
