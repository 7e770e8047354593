#pragma once

#include <string_view>

namespace rad {

// The source of shaders/NAME, embedded into the binary at build time; empty if there is no such shader.
std::string_view embedded_shader(std::string_view name);

}  // namespace rad
