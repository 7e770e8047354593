#pragma once

#include <tiny_gltf.h>

#include <cstddef>
#include <filesystem>
#include <string>

namespace rad {

// The files a glTF may read besides itself (external buffers and images): each must lie in the scene's
// folder or below it, reached without links, as an OBJ's material libraries must, so a scene cannot read
// (and echo in messages) files its author did not ship with it. Everything read together stays within the
// scene file limit. tinygltf reads files itself, so this is given to it as its file system callbacks.
class GltfFileAccess {
  public:
    GltfFileAccess(std::filesystem::path folder, std::size_t byte_budget);
    GltfFileAccess(const GltfFileAccess&) = delete;
    GltfFileAccess& operator=(const GltfFileAccess&) = delete;

    // Callbacks bound to this object; it must outlive their use.
    tinygltf::FsCallbacks callbacks();

    // Why the first file refused was refused ("uri '../x.bin' reaches outside the scene's folder"); empty
    // when none was.
    const std::string& refusal() const { return refusal_; }

  private:
    static bool exists(const std::string& uri, void* self);
    static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& uri, void* self);

    // The path to read for `uri`, or empty (with the reason in `why`) when the rule refuses it or it does
    // not exist.
    std::filesystem::path resolve(const std::string& uri, std::string& why) const;
    void refuse(const std::string& why);

    std::filesystem::path folder_;
    std::size_t budget_;
    std::string refusal_;
};

}  // namespace rad
