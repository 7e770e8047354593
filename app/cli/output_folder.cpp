#include "cli/output_folder.hpp"

#include <filesystem>

#include "rad/util/error.hpp"

namespace rad {

void require_output_folder(std::string_view option, const std::string& path) {
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty() && !std::filesystem::is_directory(folder)) {
        throw InputError(std::string(option) + " " + path + ": the folder " + folder.string() +
                         " does not exist");
    }
}

}  // namespace rad
