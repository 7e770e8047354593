#pragma once

#include <CLI/CLI.hpp>

#include "gl/headless_context.hpp"

namespace rad {

// --gl-platform auto|egl|osmesa: where a command without a window gets its OpenGL context.
void add_gl_platform_option(CLI::App& command, HeadlessPlatform& platform);

}  // namespace rad
