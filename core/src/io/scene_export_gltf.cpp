// The glTF 2.0 export, written by tinygltf (Debian's shared library, which holds its implementation): one
// buffer, one mesh of one triangle primitive, one node, an unlit material.
#include <tiny_gltf.h>

#include <cstring>
#include <fstream>
#include <glm/common.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "rad/io/scene_export.hpp"

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

        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.attributes["POSITION"] = add_positions(mesh.positions);
        primitive.attributes["NORMAL"] = add_vectors(mesh.normals);
        primitive.attributes["COLOR_0"] = add_vectors(shown);
        // An application-specific attribute (leading underscore, as the specification asks): viewers ignore
        // it, tools that want the physical values read it.
        primitive.attributes["_RADIANCE"] = add_vectors(radiance);
        primitive.indices = add_indices(mesh.triangles);
        primitive.material = add_unlit_material();

        tinygltf::Mesh gltf_mesh;
        gltf_mesh.name = "radiosity";
        gltf_mesh.primitives.push_back(std::move(primitive));
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
    // Appends the bytes as a buffer view of their own; returns the view's index.
    int add_view(const void* data, std::size_t bytes, int target) {
        std::vector<unsigned char>& buffer = model_.buffers[0].data;
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
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
    int add_unlit_material() {
        tinygltf::Material material;
        material.name = "radiosity unlit";
        material.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
        material.pbrMetallicRoughness.metallicFactor = 0.0;
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
        material.extensions[kUnlit] = tinygltf::Value(tinygltf::Value::Object());
        model_.materials.push_back(std::move(material));
        model_.extensionsUsed.push_back(kUnlit);
        return static_cast<int>(model_.materials.size() - 1);
    }

    tinygltf::Model model_;
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
