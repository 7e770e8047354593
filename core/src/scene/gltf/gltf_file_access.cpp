#include "scene/gltf/gltf_file_access.hpp"

#include <utility>

#include "rad/util/error.hpp"
#include "scene/scene_folder.hpp"
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
    fs::path path = file_in_scene_folder(folder_, uri, why);
    if (!why.empty()) why = "uri " + quote_for_message(uri) + " " + why;
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
