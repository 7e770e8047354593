#include "rad/io/output_path.hpp"

#include <filesystem>

#include "rad/util/error.hpp"

namespace rad {

void require_output_folder(std::string_view setting, const std::string& path) {
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder))
        throw SettingError(std::string(setting),
                           path + ": the folder " + folder.string() + " does not exist");
}

}  // namespace rad
