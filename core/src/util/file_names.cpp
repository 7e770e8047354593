#include "rad/util/file_names.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace rad {

std::string lowercase_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

}  // namespace rad
