#include "scene/gltf/gltf_file_access.hpp"

#include <utility>

#include "rad/util/error.hpp"
#include "scene/text_file.hpp"

namespace rad {

namespace fs = std::filesystem;

GltfFileAccess::GltfFileAccess(fs::path folder, std::size_t byte_budget)
    : folder_(std::move(folder)), budget_(byte_budget) {}

tinygltf::FsCallbacks GltfFileAccess::callbacks() {
    tinygltf::FsCallbacks fs{};
    fs.FileExists = &GltfFileAccess::exists;
    // tinygltf is given the bare URI (no base folder), which resolve() places in the scene's folder.
    fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
    fs.ReadWholeFile = &GltfFileAccess::read;
    fs.WriteWholeFile = [](std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
        if (err) *err += "writing is not allowed while loading";
        return false;
    };
    fs.user_data = this;
    return fs;
}

void GltfFileAccess::refuse(const std::string& why) {
    if (refusal_.empty()) refusal_ = why;
}

fs::path GltfFileAccess::resolve(const std::string& uri, std::string& why) const {
    const fs::path name(uri);
    const std::string quoted = "uri " + quote_for_message(uri);
    if (name.is_absolute()) {
        why = quoted + " is an absolute path; it must lie in the scene's folder";
        return {};
    }
    const fs::path relative = name.lexically_normal();
    if (relative.empty() || *relative.begin() == ".." || relative == ".") {
        why = quoted + " reaches outside the scene's folder";
        return {};
    }
    fs::path path = folder_;
    for (const fs::path& part : relative) {
        path /= part;
        std::error_code ec;
        const fs::file_status status = fs::symlink_status(path, ec);
        if (status.type() == fs::file_type::not_found || ec == std::errc::filename_too_long) return {};
        if (ec) {
            why = quoted + " cannot be inspected: " + ec.message();
            return {};
        }
        if (fs::is_symlink(status)) {
            why = quoted + " is reached through a link";
            return {};
        }
    }
    std::error_code ec;
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) {
        why = quoted + " is not a regular file";
        return {};
    }
    return path;
}

bool GltfFileAccess::exists(const std::string& uri, void* self) {
    auto& access = *static_cast<GltfFileAccess*>(self);
    std::string why;
    const bool found = !access.resolve(uri, why).empty();
    if (!why.empty()) access.refuse(why);
    return found;
}

bool GltfFileAccess::read(std::vector<unsigned char>* out, std::string* err, const std::string& uri,
                          void* self) {
    auto& access = *static_cast<GltfFileAccess*>(self);
    std::string why;
    const fs::path path = access.resolve(uri, why);
    if (path.empty()) {
        access.refuse(why.empty() ? "uri " + quote_for_message(uri) + " vanished while it was read" : why);
        if (err) *err += access.refusal_;
        return false;
    }
    try {
        const std::string bytes = read_text_file(path.string(), access.budget_);
        access.budget_ -= bytes.size();
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        access.refuse(e.what());
        if (err) *err += e.what();
        return false;
    }
}

}  // namespace rad
