#include "scene/gltf/gltf_accessors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "rad/util/error.hpp"

namespace rad {

namespace {

[[noreturn]] void refuse(const GltfFile& file, const std::string& what) {
    throw InputError(gltf_message(file, what));
}

std::string accessor_name(int accessor) {
    return "accessors[" + std::to_string(accessor) + "]";
}

std::size_t component_size(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        case TINYGLTF_COMPONENT_TYPE_DOUBLE:
            return 8;
        default:
            return 0;
    }
}

std::size_t component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;
    }
}

// Whether `count` elements of `element_size` bytes, `stride` apart, starting at `offset`, fit in `length`
// bytes, without overflow.
bool elements_fit(std::size_t offset, std::size_t count, std::size_t stride, std::size_t element_size,
                  std::size_t length) {
    if (count == 0) return offset <= length;
    if (offset > length || length - offset < element_size) return false;
    return (count - 1) <= (length - offset - element_size) / stride;
}

std::string type_name(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        default:
            return "type " + std::to_string(type);
    }
}

}  // namespace

std::span<const unsigned char> checked_buffer_view(const GltfFile& file, int view, const std::string& where) {
    const auto& views = file.model.bufferViews;
    if (view < 0 || static_cast<std::size_t>(view) >= views.size())
        refuse(file, where + ": buffer view " + std::to_string(view) + " does not exist (" +
                         std::to_string(views.size()) + " in the file)");
    const tinygltf::BufferView& v = views[static_cast<std::size_t>(view)];
    const std::string name = "bufferViews[" + std::to_string(view) + "]";
    const auto& buffers = file.model.buffers;
    if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= buffers.size())
        refuse(file, name + ": buffer " + std::to_string(v.buffer) + " does not exist (" +
                         std::to_string(buffers.size()) + " in the file)");
    const std::vector<unsigned char>& data = buffers[static_cast<std::size_t>(v.buffer)].data;
    if (v.byteOffset > data.size() || data.size() - v.byteOffset < v.byteLength)
        refuse(file, name + ": bytes " + std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
                         " exceed buffer " + std::to_string(v.buffer) + " (" + std::to_string(data.size()) +
                         " bytes)");
    return {data.data() + v.byteOffset, v.byteLength};
}

AccessorBytes checked_accessor(const GltfFile& file, int accessor, int type,
                               std::span<const int> component_types, const std::string& where) {
    const auto& accessors = file.model.accessors;
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= accessors.size())
        refuse(file, where + ": accessor " + std::to_string(accessor) + " does not exist (" +
                         std::to_string(accessors.size()) + " in the file)");
    const tinygltf::Accessor& a = accessors[static_cast<std::size_t>(accessor)];
    const std::string name = accessor_name(accessor);
    if (a.sparse.isSparse) refuse(file, name + ": sparse accessors are not supported");
    if (a.bufferView < 0) refuse(file, name + ": an accessor without a buffer view is not supported");
    if (a.type != type)
        refuse(file, name + ": " + type_name(a.type) + " where " + where + " needs " + type_name(type));
    if (std::find(component_types.begin(), component_types.end(), a.componentType) == component_types.end())
        refuse(file, name + ": component type " + std::to_string(a.componentType) + " is not one " + where +
                         " takes");
    const std::span<const unsigned char> view = checked_buffer_view(file, a.bufferView, name);
    const tinygltf::BufferView& v = file.model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    AccessorBytes bytes;
    bytes.element_size = component_size(a.componentType) * component_count(a.type);
    bytes.stride = v.byteStride != 0 ? v.byteStride : bytes.element_size;
    if (bytes.stride < bytes.element_size)
        refuse(file, name + ": byte stride " + std::to_string(bytes.stride) +
                         " is shorter than an element (" + std::to_string(bytes.element_size) + " bytes)");
    if (!elements_fit(a.byteOffset, a.count, bytes.stride, bytes.element_size, view.size()))
        refuse(file, name + ": count " + std::to_string(a.count) + " at byte offset " +
                         std::to_string(a.byteOffset) + " exceeds buffer view " +
                         std::to_string(a.bufferView) + " (" + std::to_string(view.size()) + " bytes)");
    bytes.data = view.data() + a.byteOffset;
    bytes.count = a.count;
    return bytes;
}

std::vector<glm::dvec3> read_positions(const GltfFile& file, int accessor, std::size_t max_count,
                                       const std::string& where) {
    const int types[] = {TINYGLTF_COMPONENT_TYPE_FLOAT};
    const AccessorBytes bytes = checked_accessor(file, accessor, TINYGLTF_TYPE_VEC3, types, where);
    if (bytes.count > max_count)
        refuse(file, accessor_name(accessor) + ": " + std::to_string(bytes.count) +
                         " positions exceed the limit of " + std::to_string(max_count));
    std::vector<glm::dvec3> positions(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
        float xyz[3];
        std::memcpy(xyz, bytes.data + i * bytes.stride, sizeof xyz);  // the buffer need not be aligned
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
            refuse(file, accessor_name(accessor) + ": position " + std::to_string(i) + " is not finite");
        positions[i] = {xyz[0], xyz[1], xyz[2]};
    }
    return positions;
}

std::vector<glm::dvec2> read_texcoords(const GltfFile& file, int accessor, std::size_t vertex_count,
                                       const std::string& where) {
    const int types[] = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
    const AccessorBytes bytes = checked_accessor(file, accessor, TINYGLTF_TYPE_VEC2, types, where);
    if (bytes.count != vertex_count)
        refuse(file, accessor_name(accessor) + ": " + std::to_string(bytes.count) +
                         " texture coordinates for " + std::to_string(vertex_count) + " positions");
    std::vector<glm::dvec2> uv(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* p = bytes.data + i * bytes.stride;
        for (int c = 0; c < 2; ++c) {
            if (bytes.element_size == 8) {
                float v;
                std::memcpy(&v, p + 4 * c, sizeof v);
                if (!std::isfinite(v))
                    refuse(file, accessor_name(accessor) + ": texture coordinate " + std::to_string(i) +
                                     " is not finite");
                uv[i][c] = v;
            } else if (bytes.element_size == 4) {
                std::uint16_t v;
                std::memcpy(&v, p + 2 * c, sizeof v);
                uv[i][c] = v / 65535.0;
            } else {
                uv[i][c] = p[c] / 255.0;
            }
        }
    }
    return uv;
}

std::vector<std::uint32_t> read_indices(const GltfFile& file, int accessor, std::size_t vertex_count,
                                        std::size_t max_count, const std::string& where) {
    const int types[] = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
    const AccessorBytes bytes = checked_accessor(file, accessor, TINYGLTF_TYPE_SCALAR, types, where);
    if (bytes.count > max_count)
        refuse(file, accessor_name(accessor) + ": " + std::to_string(bytes.count) +
                         " indices exceed the limit of " + std::to_string(max_count));
    std::vector<std::uint32_t> indices(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* p = bytes.data + i * bytes.stride;
        std::uint32_t index = 0;
        if (bytes.element_size == 1) {
            index = *p;
        } else if (bytes.element_size == 2) {
            std::uint16_t v;
            std::memcpy(&v, p, sizeof v);
            index = v;
        } else {
            std::memcpy(&index, p, sizeof index);
        }
        if (index >= vertex_count)
            refuse(file, accessor_name(accessor) + ": index " + std::to_string(index) + " (element " +
                             std::to_string(i) + ") is out of range (" + std::to_string(vertex_count) +
                             " vertices)");
        indices[i] = index;
    }
    return indices;
}

}  // namespace rad
