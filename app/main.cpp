// radiosity: computes diffuse global illumination once and shows it from any viewpoint.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/command_line.hpp"
#include "rad/util/error.hpp"
#include "text/input_error_message.hpp"

namespace {

int run(int argc, char** argv) {
    rad::CommandLine command_line;
    CLI::App& app = command_line.app();
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
    return command_line.run_chosen_command();
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const rad::InputError& e) {
        std::cerr << "radiosity: error: " << rad::input_error_message(e) << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "radiosity: failed: " << e.what() << '\n';
        return 1;
    }
}
