// radiosity: computes diffuse global illumination once and shows it from any viewpoint.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "rad/error.hpp"
#include "scene_options.hpp"
#include "scene_summary.hpp"

namespace {

int print_summary(const rad::SceneOptions& options) {
    rad::print_scene_summary(std::cout, rad::load_and_mesh(options));
    return 0;
}

int run(int argc, char** argv) {
    CLI::App app{"radiosity: diffuse global illumination by the radiosity method"};
    app.require_subcommand(0, 1);

    rad::SceneOptions view_options;
    CLI::App* view = app.add_subcommand("view", "Show SCENE (default command; prints its summary until the "
                                                "interactive viewer lands)");
    rad::add_scene_options(*view, view_options);

    rad::SceneOptions info_options;
    CLI::App* info = app.add_subcommand("info", "Print SCENE's surfaces, materials, patch count, area and bounds");
    rad::add_scene_options(*info, info_options);

    // `radiosity SCENE` with no command means `radiosity view SCENE`.
    rad::SceneOptions default_options;
    rad::add_scene_options(app, default_options);

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

    if (*info) return print_summary(info_options);
    if (*view) return print_summary(view_options);
    return print_summary(default_options);
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
