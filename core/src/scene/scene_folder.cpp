#include "scene/scene_folder.hpp"

#include <system_error>

namespace rad {

std::filesystem::path file_in_scene_folder(const std::filesystem::path& folder, const std::string& name,
                                           std::string& why) {
    namespace fs = std::filesystem;
    const fs::path given(name);
    if (given.is_absolute()) {
        why = "is an absolute path; it must lie in the scene's folder";
        return {};
    }
    const fs::path relative = given.lexically_normal();
    if (relative.empty() || *relative.begin() == ".." || relative == ".") {
        why = "reaches outside the scene's folder";
        return {};
    }
    fs::path path = folder;
    for (const fs::path& part : relative) {
        path /= part;
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(path, ec);
        // A name longer than the file system allows cannot exist either.
        if (status.type() == fs::file_type::not_found || ec == std::errc::filename_too_long) return {};
        if (ec) {
            why = "cannot be inspected: " + ec.message();
            return {};
        }
        if (fs::is_symlink(status)) {
            why = "is reached through a link (" + path.string() + ")";
            return {};
        }
    }
    std::error_code ec;
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) {
        why = "is not a regular file";
        return {};
    }
    return path;
}

}  // namespace rad
