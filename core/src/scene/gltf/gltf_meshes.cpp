#include "scene/gltf/gltf_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "rad/util/error.hpp"
#include "scene/gltf/gltf_accessors.hpp"
#include "scene/gltf/gltf_quads.hpp"
#include "scene/scene_limits.hpp"

namespace rad {

namespace {

[[noreturn]] void refuse(const GltfFile& file, const std::string& what) {
    throw InputError(gltf_message(file, what));
}

// Corner triples of a primitive's triangles, from its index list (or 0, 1, 2, ... when it has none). Empty
// for points and lines.
std::vector<std::uint32_t> triangle_corners(int mode, const std::vector<std::uint32_t>& index) {
    std::vector<std::uint32_t> corners;
    const std::size_t n = index.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        corners.assign(index.begin(), index.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < n; ++i) {
            // Every other triangle of a strip runs the other way; swapping two corners keeps them all facing
            // one side.
            const bool odd = i % 2 == 1;
            corners.insert(corners.end(), {index[i + (odd ? 1 : 0)], index[i + (odd ? 0 : 1)], index[i + 2]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 1; i + 1 < n; ++i)
            corners.insert(corners.end(), {index[0], index[i], index[i + 1]});
    }
    return corners;
}

bool is_triangles(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

class MeshReader {
  public:
    MeshReader(GltfFile& file, const std::vector<Material>& materials, PolygonSoup& soup)
        : file_(file), materials_(materials), soup_(soup) {}

    void add_node(const PlacedNode& placed) {
        const int mesh = file_.model.nodes[static_cast<std::size_t>(placed.node)].mesh;
        if (mesh < 0) return;
        const auto& meshes = file_.model.meshes;
        if (static_cast<std::size_t>(mesh) >= meshes.size())
            refuse(file_, "nodes[" + std::to_string(placed.node) + "]: mesh " + std::to_string(mesh) +
                              " does not exist (" + std::to_string(meshes.size()) + " in the file)");
        const auto& primitives = meshes[static_cast<std::size_t>(mesh)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) add_primitive(placed, mesh, p);
    }

    std::size_t skipped() const { return skipped_; }
    std::size_t ragged() const { return ragged_; }
    std::size_t without_material() const { return without_material_; }
    std::size_t without_texcoords() const { return without_texcoords_; }

  private:
    void add_primitive(const PlacedNode& placed, int mesh, std::size_t p) {
        const tinygltf::Primitive& primitive =
            file_.model.meshes[static_cast<std::size_t>(mesh)].primitives[p];
        if (!is_triangles(primitive.mode)) {
            ++skipped_;
            return;
        }
        const std::string where =
            "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(p) + "]";
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) refuse(file_, where + ": has no POSITION attribute");
        const std::vector<glm::dvec3> local =
            read_positions(file_, position->second, kMaxSceneVertices - soup_.positions.size(), where);
        const std::vector<std::uint32_t> index =
            primitive.indices >= 0
                ? read_indices(file_, primitive.indices, local.size(), kMaxSceneFaceCorners, where)
                : all_vertices(local.size());
        if (primitive.mode == TINYGLTF_MODE_TRIANGLES && index.size() % 3 != 0) ++ragged_;
        const std::vector<std::uint32_t> corners = triangle_corners(primitive.mode, index);
        if (soup_.polygons.size() + corners.size() / 3 > kMaxSceneFaces)
            refuse(file_, where + ": the scene's triangles would exceed the limit of " +
                              std::to_string(kMaxSceneFaces));

        const auto base = static_cast<std::uint32_t>(soup_.positions.size());
        for (const glm::dvec3& p_local : local)
            soup_.positions.push_back(world_position(placed, p_local, where));
        // A transform that mirrors reverses the winding, which glTF's front faces follow.
        const bool mirrored = glm::determinant(glm::dmat3(placed.world)) < 0.0;
        const std::uint32_t group = group_of(mesh, primitive.material, where);
        const bool textured = add_texcoords(primitive, local.size(), where);
        const auto uv_base =
            static_cast<std::uint32_t>(soup_.texcoords.size() - (textured ? local.size() : 0));
        for (std::vector<std::uint32_t>& vertices : merge_triangle_pairs(corners, local)) {
            if (mirrored) std::reverse(vertices.begin(), vertices.end());
            PolygonSoup::Polygon polygon;
            polygon.group = group;
            for (std::uint32_t& v : vertices) {
                if (textured) polygon.texcoords.push_back(v + uv_base);
                v += base;
            }
            polygon.vertices = std::move(vertices);
            soup_.polygons.push_back(std::move(polygon));
        }
    }

    // Appends the primitive's texture coordinates (one per vertex) when its material has a base colour
    // texture and the primitive the coordinate set it names; returns whether it did.
    bool add_texcoords(const tinygltf::Primitive& primitive, std::size_t vertices, const std::string& where) {
        if (primitive.material < 0 || !materials_[static_cast<std::size_t>(primitive.material)].texture)
            return false;
        const int set = file_.model.materials[static_cast<std::size_t>(primitive.material)]
                            .pbrMetallicRoughness.baseColorTexture.texCoord;
        const auto uv = primitive.attributes.find("TEXCOORD_" + std::to_string(set));
        if (uv == primitive.attributes.end()) {
            ++without_texcoords_;
            return false;
        }
        const std::vector<glm::dvec2> read = read_texcoords(file_, uv->second, vertices, where);
        soup_.texcoords.insert(soup_.texcoords.end(), read.begin(), read.end());
        return true;
    }

    static std::vector<std::uint32_t> all_vertices(std::size_t count) {
        std::vector<std::uint32_t> index(count);
        for (std::size_t i = 0; i < count; ++i) index[i] = static_cast<std::uint32_t>(i);
        return index;
    }

    glm::dvec3 world_position(const PlacedNode& placed, const glm::dvec3& p, const std::string& where) const {
        const glm::dvec4 w = placed.world * glm::dvec4(p, 1.0);
        const glm::dvec3 q = glm::dvec3(w) / w.w;
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(q[c]) || std::abs(q[c]) > kMaxCoordinate)
                refuse(file_, where + " in nodes[" + std::to_string(placed.node) +
                                  "]: a position beyond 1e30 (or not finite) once transformed");
        }
        return q;
    }

    std::uint32_t group_of(int mesh, int material, const std::string& where) {
        if (material >= 0 && static_cast<std::size_t>(material) >= materials_.size())
            refuse(file_, where + ": material " + std::to_string(material) + " does not exist (" +
                              std::to_string(materials_.size()) + " in the file)");
        const auto key = std::make_pair(mesh, material);
        if (const auto it = groups_.find(key); it != groups_.end()) return it->second;
        const Material m =
            material >= 0 ? materials_[static_cast<std::size_t>(material)] : default_material();
        if (material < 0) ++without_material_;
        soup_.groups.push_back({group_name(mesh, m), m});
        return groups_[key] = static_cast<std::uint32_t>(soup_.groups.size() - 1);
    }

    // The mesh's name, and the material's after a slash when the mesh has several, as the OBJ loader names
    // objects split by usemtl.
    std::string group_name(int mesh, const Material& material) const {
        const tinygltf::Mesh& m = file_.model.meshes[static_cast<std::size_t>(mesh)];
        std::set<int> used;
        for (const auto& primitive : m.primitives) used.insert(primitive.material);
        const std::string name = gltf_name(m.name, "mesh " + std::to_string(mesh));
        return used.size() > 1 ? name + "/" + material.name : name;
    }

    GltfFile& file_;
    const std::vector<Material>& materials_;
    PolygonSoup& soup_;
    std::map<std::pair<int, int>, std::uint32_t> groups_;
    std::size_t skipped_ = 0;
    std::size_t ragged_ = 0;  // triangle lists whose count of corners is not a multiple of 3
    std::size_t without_material_ = 0;
    std::size_t without_texcoords_ = 0;  // textured primitives without the coordinates their texture needs
};

}  // namespace

void add_meshes(GltfFile& file, const std::vector<PlacedNode>& nodes, const std::vector<Material>& materials,
                PolygonSoup& soup) {
    MeshReader reader(file, materials, soup);
    for (const PlacedNode& placed : nodes) reader.add_node(placed);
    if (reader.skipped() > 0)
        file.warnings.push_back(gltf_message(
            file, "skipped " + std::to_string(reader.skipped()) +
                      " primitive(s) that are not triangles (points, lines, or an unknown mode)"));
    if (reader.ragged() > 0)
        file.warnings.push_back(gltf_message(
            file, std::to_string(reader.ragged()) +
                      " triangle primitive(s) have a corner count that is not a multiple of 3; the 1 or 2 "
                      "corners left over are ignored"));
    if (reader.without_texcoords() > 0)
        file.warnings.push_back(gltf_message(
            file, std::to_string(reader.without_texcoords()) +
                      " textured primitive(s) have no texture coordinates; they show their material's mean "
                      "colour"));
    if (reader.without_material() > 0)
        file.warnings.push_back(
            gltf_message(file, std::to_string(reader.without_material()) +
                                   " mesh(es) have primitives without a material; they use the "
                                   "default: reflectance 0.5, no emission"));
}

}  // namespace rad
