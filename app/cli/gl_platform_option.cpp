#include "cli/gl_platform_option.hpp"

#include <string>

namespace rad {

void add_gl_platform_option(CLI::App& command, HeadlessPlatform& platform) {
    command
        .add_option_function<std::string>(
            "--gl-platform",
            [&platform](const std::string& name) {
                platform = name == "egl"      ? HeadlessPlatform::egl
                           : name == "osmesa" ? HeadlessPlatform::osmesa
                                              : HeadlessPlatform::automatic;
            },
            "Where the OpenGL context comes from: auto (EGL, then OSMesa when EGL gives none), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}))
        ->default_str("auto");
}

}  // namespace rad
