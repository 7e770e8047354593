#include <cstring>
#include <filesystem>
#include <sstream>

#include "rad/util/error.hpp"
#include "scene/gltf/gltf_accessors.hpp"
#include "scene/gltf/gltf_file.hpp"
#include "scene/gltf/gltf_file_access.hpp"
#include "scene/text_file.hpp"
#include "scene/texture_image.hpp"

namespace rad {

namespace {

// tinygltf's messages are lines ending in '\n'; ours are one line.
std::string one_line(const std::string& text) {
    std::string line;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part);) {
        if (part.empty()) continue;
        if (!line.empty()) line += "; ";
        line += part;
    }
    return line;
}

std::uint32_t read_u32(const std::string& bytes, std::size_t at) {
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, sizeof value);  // GLB is little-endian, as are our machines
    return value;
}

// tinygltf 2.7 checks the BIN chunk's length against the GLB's declared length but leaves out the chunk's
// 8-byte header, so a chunk that claims to end at the file's end would be read 8 bytes past it: the chunk
// framing is checked here first. The rest (magic, JSON, buffers) tinygltf checks itself.
void check_glb_framing(const std::string& path, const std::string& bytes) {
    if (bytes.size() < 20) return;  // tinygltf refuses it
    const std::uint64_t length = read_u32(bytes, 8);
    const std::uint64_t json_end = 20 + std::uint64_t{read_u32(bytes, 12)};
    if (length > bytes.size() || json_end > length)
        throw InputError(path + ": GLB chunks exceed the file (" + std::to_string(bytes.size()) + " bytes)");
    if (json_end == length) return;
    if (length - json_end < 8 || length - json_end - 8 < read_u32(bytes, json_end))
        throw InputError(path + ": GLB binary chunk exceeds the file (" + std::to_string(bytes.size()) +
                         " bytes)");
}

// What tinygltf's image callback works with: the file, for messages and results.
struct ImageDecoding {
    GltfFile* file;
};

void decode_image(GltfFile& file, int index, const unsigned char* bytes, std::size_t size) {
    std::string why;
    const std::string name = "images[" + std::to_string(index) + "]";
    if (auto texture = decode_texture(bytes, size, name, why)) {
        file.images[index] = std::move(texture);
    } else {
        file.warnings.push_back(gltf_message(file, "images[" + std::to_string(index) + "]: not used: " + why +
                                                       "; its materials take their factors alone"));
    }
}

// tinygltf's image callback. An image in a buffer view is left for decode_buffer_view_images: tinygltf passes
// its bytes without checking the view against its buffer. Images are decoded into our own textures, so
// tinygltf keeps no texels.
bool load_image(tinygltf::Image* image, int index, std::string*, std::string*, int, int,
                const unsigned char* bytes, int size, void* user) {
    if (image->bufferView >= 0) return true;
    decode_image(*static_cast<ImageDecoding*>(user)->file, index, bytes, static_cast<std::size_t>(size));
    return true;
}

void decode_buffer_view_images(GltfFile& file) {
    const auto& images = file.model.images;
    for (std::size_t i = 0; i < images.size(); ++i) {
        if (images[i].bufferView < 0) continue;
        const std::string where = "images[" + std::to_string(i) + "]";
        const std::span<const unsigned char> view = checked_buffer_view(file, images[i].bufferView, where);
        decode_image(file, static_cast<int>(i), view.data(), view.size());
    }
}

bool is_glb(const std::string& bytes) {
    return bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
}

}  // namespace

std::string gltf_name(const std::string& name, const std::string& fallback) {
    if (name.empty()) return fallback;
    std::string clean = name;
    for (char& c : clean)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return clean;
}

std::string gltf_message(const GltfFile& file, const std::string& what) {
    return file.path + ": " + what;
}

GltfFile read_gltf(const std::string& path) {
    GltfFile file;
    file.path = path;
    const std::string bytes = read_text_file(path);
    const bool glb = is_glb(bytes);
    if (glb) check_glb_framing(path, bytes);

    GltfFileAccess access(std::filesystem::path(path).parent_path(), kMaxSceneFileBytes - bytes.size());
    tinygltf::TinyGLTF reader;
    reader.SetFsCallbacks(access.callbacks());
    ImageDecoding decoding{&file};
    reader.SetImageLoader(&load_image, &decoding);
    std::string err, warn;
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const auto size = static_cast<unsigned int>(bytes.size());  // at most kMaxSceneFileBytes
    // No base folder: GltfFileAccess places the URIs in the scene's folder itself.
    bool ok = false;
    try {
        ok = glb ? reader.LoadBinaryFromMemory(&file.model, &err, &warn, data, size, "")
                 : reader.LoadASCIIFromString(&file.model, &err, &warn, bytes.data(), size, "");
    } catch (const std::exception& e) {
        // tinygltf reports by its return value, but a container's at() or the JSON library may still throw.
        throw InputError(gltf_message(file, "tinygltf cannot read it: " + one_line(e.what())));
    }
    if (!access.refusal().empty()) throw InputError(gltf_message(file, access.refusal()));
    if (!ok) throw InputError(gltf_message(file, err.empty() ? "tinygltf cannot read it" : one_line(err)));
    if (!warn.empty()) file.warnings.insert(file.warnings.begin(), gltf_message(file, one_line(warn)));
    decode_buffer_view_images(file);
    return file;
}

}  // namespace rad
