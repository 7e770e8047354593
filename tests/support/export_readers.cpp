#include "export_readers.hpp"

// OpenMesh's IO header must come before any mesh header.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "rad/util/file_names.hpp"

namespace rad::test {

namespace {

struct ReadTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3f;
    using Normal = OpenMesh::Vec3f;
    using Color = OpenMesh::Vec3f;  // OpenMesh reads 8-bit colours as byte / 255
};
using ReadMesh = OpenMesh::TriMesh_ArrayKernelT<ReadTraits>;

std::vector<float> float_property(const ReadMesh& mesh, const char* name) {
    OpenMesh::VPropHandleT<float> handle;
    if (!mesh.get_property_handle(handle, name)) throw std::runtime_error(std::string("no property ") + name);
    std::vector<float> values;
    for (auto v : mesh.vertices()) values.push_back(mesh.property(handle, v));
    return values;
}

// The accessor's elements as raw bytes, checked against the component type and type the export promises.
std::vector<unsigned char> accessor_bytes(const tinygltf::Model& model, int index, int component_type,
                                          int type) {
    const tinygltf::Accessor& accessor = model.accessors.at(static_cast<std::size_t>(index));
    if (accessor.componentType != component_type || accessor.type != type) {
        throw std::runtime_error("accessor " + std::to_string(index) + " has an unexpected type");
    }
    const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
    const std::size_t element = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(component_type) *
                                                         tinygltf::GetNumComponentsInType(type));
    if (view.byteStride != 0 && view.byteStride != element) throw std::runtime_error("unexpected stride");
    const std::vector<unsigned char>& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer)).data;
    const std::size_t begin = view.byteOffset + accessor.byteOffset;
    const std::size_t bytes = accessor.count * element;
    if (begin + bytes > buffer.size() || accessor.byteOffset + bytes > view.byteLength) {
        throw std::runtime_error("accessor " + std::to_string(index) + " runs past its buffer");
    }
    return {buffer.begin() + static_cast<std::ptrdiff_t>(begin),
            buffer.begin() + static_cast<std::ptrdiff_t>(begin + bytes)};
}

template <typename T>
std::vector<T> accessor_values(const tinygltf::Model& model, int index, int component_type, int type) {
    const std::vector<unsigned char> bytes = accessor_bytes(model, index, component_type, type);
    std::vector<T> values(bytes.size() / sizeof(T));
    std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
    return values;
}

std::vector<glm::vec3> vec3_attribute(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                      const std::string& name) {
    const auto it = primitive.attributes.find(name);
    if (it == primitive.attributes.end()) throw std::runtime_error("no attribute " + name);
    return accessor_values<glm::vec3>(model, it->second, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
}

}  // namespace

ExportedMesh read_ply_export(const std::string& path) {
    ReadMesh mesh;
    mesh.request_vertex_colors();
    mesh.request_vertex_normals();
    OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor | OpenMesh::IO::Options::VertexNormal |
                                    OpenMesh::IO::Options::Custom;
    if (!OpenMesh::IO::read_mesh(mesh, path, options))
        throw std::runtime_error(path + ": OpenMesh cannot read it");
    if (!options.vertex_has_color() || !options.vertex_has_normal()) {
        throw std::runtime_error(path + ": no vertex colours or normals");
    }
    ExportedMesh exported;
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        const auto& n = mesh.normal(v);
        const auto& c = mesh.color(v);
        exported.positions.emplace_back(p[0], p[1], p[2]);
        exported.normals.emplace_back(n[0], n[1], n[2]);
        const auto byte = [](float value) { return static_cast<std::uint8_t>(std::lround(255.0f * value)); };
        exported.colour_bytes.push_back({byte(c[0]), byte(c[1]), byte(c[2])});
    }
    const std::vector<float> r = float_property(mesh, "radiance_r");
    const std::vector<float> g = float_property(mesh, "radiance_g");
    const std::vector<float> b = float_property(mesh, "radiance_b");
    for (std::size_t v = 0; v < r.size(); ++v) exported.radiance.emplace_back(r[v], g[v], b[v]);
    for (auto f : mesh.faces()) {
        glm::uvec3 triangle(0);
        int k = 0;
        for (auto v : mesh.fv_range(f)) {
            if (k == 3) throw std::runtime_error(path + ": a face with more than three corners");
            triangle[k++] = static_cast<unsigned>(v.idx());
        }
        exported.triangles.push_back(triangle);
    }
    return exported;
}

ExportedMesh read_gltf_export(const std::string& path, tinygltf::Model* model_out) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    const bool binary = lowercase_extension(path) == ".glb";
    const bool loaded = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                               : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    if (!loaded || !error.empty()) throw std::runtime_error(path + ": tinygltf cannot load it: " + error);
    if (model.meshes.size() != 1 || model.meshes[0].primitives.empty()) {
        throw std::runtime_error(path + ": not one mesh with primitives");
    }
    const std::vector<tinygltf::Primitive>& primitives = model.meshes[0].primitives;
    const tinygltf::Primitive& primitive = primitives[0];
    ExportedMesh exported;
    exported.positions = vec3_attribute(model, primitive, "POSITION");
    exported.normals = vec3_attribute(model, primitive, "NORMAL");
    exported.colours = vec3_attribute(model, primitive, "COLOR_0");
    exported.radiance = vec3_attribute(model, primitive, "_RADIANCE");
    for (const tinygltf::Primitive& p : primitives) {
        if (p.attributes != primitive.attributes)
            throw std::runtime_error(path + ": primitives that do not share their vertices");
        const std::vector<std::uint32_t> indices = accessor_values<std::uint32_t>(
            model, p.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR);
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
            exported.triangles.emplace_back(indices[i], indices[i + 1], indices[i + 2]);
        }
    }
    if (model_out) *model_out = std::move(model);
    return exported;
}

}  // namespace rad::test
