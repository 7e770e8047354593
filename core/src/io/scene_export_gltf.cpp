// The glTF 2.0 export, written by tinygltf (Debian's shared library, which holds its implementation): one
// buffer, one mesh of triangle primitives (one per textured range, one for the rest), one node, unlit
// materials.
#include <tiny_gltf.h>

#include <cstring>
#include <fstream>
#include <glm/common.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "rad/io/scene_export.hpp"
#include "rad/util/srgb.hpp"

namespace rad {

namespace {

constexpr const char* kUnlit = "KHR_materials_unlit";

class GltfBuilder {
  public:
    tinygltf::Model build(const DisplayMesh& mesh, std::span<const glm::vec3> radiance, double exposure) {
        model_.asset.version = "2.0";
        model_.asset.generator = "radiosity";
        model_.buffers.emplace_back();

        std::vector<glm::vec3> shown(radiance.size());
        for (std::size_t v = 0; v < radiance.size(); ++v) shown[v] = displayed_value(radiance[v], exposure);

        // Every primitive shares the vertices; each textured range is a primitive of its own, whose COLOR_0
        // (the irradiance / π its vertices carry) the viewer multiplies by the texture's albedo.
        tinygltf::Primitive shared;
        shared.mode = TINYGLTF_MODE_TRIANGLES;
        shared.attributes["POSITION"] = add_positions(mesh.positions);
        shared.attributes["NORMAL"] = add_vectors(mesh.normals);
        shared.attributes["COLOR_0"] = add_vectors(shown);
        // An application-specific attribute (leading underscore, as the specification asks): viewers ignore
        // it, tools that want the physical values read it. For a textured vertex, the radiance at the vertex.
        shared.attributes["_RADIANCE"] = add_vectors(vertex_shown_radiance(mesh, radiance));
        if (!mesh.textured.empty()) shared.attributes["TEXCOORD_0"] = add_texcoords(mesh.texcoords);

        tinygltf::Mesh gltf_mesh;
        gltf_mesh.name = "radiosity";
        std::size_t next = 0;
        const std::span<const glm::uvec3> triangles(mesh.triangles);
        for (const DisplayMesh::TexturedRange& range : mesh.textured) {
            if (range.first_triangle > next)
                add_primitive(shared, triangles.subspan(next, range.first_triangle - next), untextured(),
                              gltf_mesh);
            add_primitive(shared, triangles.subspan(range.first_triangle, range.triangle_count),
                          textured_material(range), gltf_mesh);
            next = range.first_triangle + range.triangle_count;
        }
        if (next < triangles.size()) add_primitive(shared, triangles.subspan(next), untextured(), gltf_mesh);
        model_.meshes.push_back(std::move(gltf_mesh));
        tinygltf::Node node;
        node.mesh = 0;
        model_.nodes.push_back(std::move(node));
        tinygltf::Scene scene;
        scene.nodes.push_back(0);
        model_.scenes.push_back(std::move(scene));
        model_.defaultScene = 0;
        return std::move(model_);
    }

  private:
    void add_primitive(const tinygltf::Primitive& shared, std::span<const glm::uvec3> triangles, int material,
                       tinygltf::Mesh& mesh) {
        tinygltf::Primitive primitive = shared;
        primitive.indices = add_indices(triangles);
        primitive.material = material;
        mesh.primitives.push_back(std::move(primitive));
    }

    int untextured() {
        if (untextured_ < 0) untextured_ = add_unlit_material("radiosity unlit", -1);
        return untextured_;
    }

    // The range's texture as an image of albedo (the texel times the range's scale, at most 1 as the
    // material's factor is), so an unlit viewer's base colour × COLOR_0 is the radiance shown.
    int textured_material(const DisplayMesh::TexturedRange& range) {
        const Texture& t = *range.texture;
        std::vector<unsigned char> albedo(t.srgb.size());
        for (std::size_t i = 0; i < albedo.size(); ++i)
            albedo[i] = srgb_byte(range.albedo_scale[static_cast<int>(i % 3)] *
                                  static_cast<float>(srgb_byte_to_linear(t.srgb[i])));
        std::vector<unsigned char> png;
        stbi_write_png_to_func(
            [](void* context, void* data, int size) {
                auto* out = static_cast<std::vector<unsigned char>*>(context);
                out->insert(out->end(), static_cast<unsigned char*>(data),
                            static_cast<unsigned char*>(data) + size);
            },
            &png, t.width, t.height, 3, albedo.data(), t.width * 3);
        if (png.empty()) throw std::runtime_error("cannot encode texture " + t.name + " as PNG");
        tinygltf::Image image;
        image.name = t.name;
        image.mimeType = "image/png";
        image.bufferView = add_view(png.data(), png.size(), 0);
        model_.images.push_back(std::move(image));
        tinygltf::Texture texture;
        texture.source = static_cast<int>(model_.images.size() - 1);
        model_.textures.push_back(texture);
        return add_unlit_material("radiosity unlit " + t.name, static_cast<int>(model_.textures.size() - 1));
    }

    int add_texcoords(std::span<const glm::vec2> values) {
        const int view = add_view(values.data(), values.size_bytes(), TINYGLTF_TARGET_ARRAY_BUFFER);
        return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, values.size());
    }

    // Appends the bytes as a buffer view of their own; returns the view's index.
    int add_view(const void* data, std::size_t bytes, int target) {
        std::vector<unsigned char>& buffer = model_.buffers[0].data;
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;  // 0 for an image
        buffer.resize(buffer.size() + bytes);
        std::memcpy(buffer.data() + view.byteOffset, data, bytes);
        model_.bufferViews.push_back(view);
        return static_cast<int>(model_.bufferViews.size() - 1);
    }

    int add_accessor(int view, int component_type, int type, std::size_t count) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = component_type;
        accessor.type = type;
        accessor.count = count;
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size() - 1);
    }

    int add_vectors(std::span<const glm::vec3> values) {
        const int view = add_view(values.data(), values.size_bytes(), TINYGLTF_TARGET_ARRAY_BUFFER);
        return add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, values.size());
    }

    // POSITION must carry its bounds.
    int add_positions(std::span<const glm::vec3> positions) {
        glm::vec3 low(std::numeric_limits<float>::max());
        glm::vec3 high(std::numeric_limits<float>::lowest());
        for (const glm::vec3& p : positions) {
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
        const int accessor = add_vectors(positions);
        model_.accessors[accessor].minValues = {low.x, low.y, low.z};
        model_.accessors[accessor].maxValues = {high.x, high.y, high.z};
        return accessor;
    }

    int add_indices(std::span<const glm::uvec3> triangles) {
        static_assert(sizeof(glm::uvec3) == 3 * sizeof(std::uint32_t));
        const int view =
            add_view(triangles.data(), triangles.size_bytes(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        return add_accessor(view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                            3 * triangles.size());
    }

    // Unlit, so viewers show COLOR_0 as it is instead of shading it again; the metallic-roughness values are
    // the extension's recommended fallback for viewers without it. One-sided, as the scene's surfaces are.
    int add_unlit_material(const std::string& name, int texture) {
        tinygltf::Material material;
        material.name = name;
        material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
        material.pbrMetallicRoughness.baseColorTexture.index = texture;
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
        material.extensions[kUnlit] = tinygltf::Value(tinygltf::Value::Object());
        model_.materials.push_back(std::move(material));
        if (model_.extensionsUsed.empty()) model_.extensionsUsed.push_back(kUnlit);
        return static_cast<int>(model_.materials.size() - 1);
    }

    tinygltf::Model model_;
    int untextured_ = -1;
};

}  // namespace

void write_gltf_export(const std::filesystem::path& path, const DisplayMesh& mesh,
                       std::span<const glm::vec3> radiance, const ExportOptions& options, bool binary) {
    const tinygltf::Model model = GltfBuilder().build(mesh, radiance, options.exposure);
    // Through our own stream, so a failed write (a full disk) is seen; text glTF embeds the buffer as base64.
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + path.string());
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/!binary, /*writeBinary=*/binary)) {
        throw std::runtime_error(path.string() + ": tinygltf could not write the glTF file");
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace rad
