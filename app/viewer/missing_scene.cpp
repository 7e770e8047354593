#include "viewer/missing_scene.hpp"

#include <filesystem>
#include <system_error>

namespace rad {

std::string missing_scene(const std::string& source) {
    if (source.starts_with("builtin:")) return {};
    std::error_code error;
    if (std::filesystem::is_regular_file(source, error)) return {};
    return "the scene this solution was solved from, " + source + ", is not found";
}

}  // namespace rad
