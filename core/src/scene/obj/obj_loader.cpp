#include <tiny_obj_loader.h>
#include <filesystem>
#include <map>
#include <set>
#include <utility>

#include "rad/scene/polygon_soup.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"
#include "scene/obj/obj_syntax.hpp"
#include "scene/obj/obj_textures.hpp"
#include "scene/scene_folder.hpp"
#include "scene/text_file.hpp"

namespace rad {

namespace {

// The text of every MTL file the OBJ names, and where each material was defined, for messages.
struct MaterialLibraries {
    std::string text;
    std::map<std::string, std::string> defined_at;  // material name -> "file:line"
};

[[noreturn]] void refuse_library(const std::string& obj_path, const ObjLibrary& lib, const std::string& why) {
    throw InputError(obj_path + ":" + std::to_string(lib.line) + ": material library " +
                     quote_for_message(lib.name) + " " + why);
}

// Returns the path to read, or empty when the library does not exist (a warning, not an error); a library
// the scene-folder rule refuses is an error.
std::filesystem::path resolve_material_library(const std::string& obj_path, const ObjLibrary& lib) {
    std::string why;
    std::filesystem::path path =
        file_in_scene_folder(std::filesystem::path(obj_path).parent_path(), lib.name, why);
    if (!why.empty()) refuse_library(obj_path, lib, why);
    return path;
}

MaterialLibraries read_material_libraries(const std::string& obj_path, const ObjFacts& facts,
                                          std::vector<std::string>& warnings) {
    MaterialLibraries libs;
    for (const ObjLibrary& lib : facts.libraries) {
        const std::filesystem::path mtl = resolve_material_library(obj_path, lib);
        if (mtl.empty()) {
            warnings.push_back(
                obj_path + ":" + std::to_string(lib.line) + ": material library " +
                quote_for_message(lib.name) +
                " not found; its materials fall back to the default (reflectance 0.5, no emission)");
            continue;
        }
        const std::string mtl_path = mtl.string();
        const std::string text = read_text_file(mtl_path);
        for (const auto& [name, line] : check_mtl_text(text, mtl_path)) {
            libs.defined_at.emplace(name, mtl_path + ":" + std::to_string(line));
        }
        libs.text += text;
        libs.text += '\n';
    }
    return libs;
}

std::string first_line(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

Material to_material(const tinyobj::material_t& m, const MaterialLibraries& libs, ReflectanceClamps& clamps,
                     ObjTextures& textures) {
    Material material;
    material.name = m.name;
    material.reflectance = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    material.emission = {m.emission[0], m.emission[1], m.emission[2]};
    clamps.clamp(material);
    textures.apply(m.diffuse_texname, material);
    const auto where = libs.defined_at.find(m.name);
    validate_material(material, where != libs.defined_at.end() ? where->second : "material library");
    return material;
}

// Transparency (`d` below 1, or `Tr` above 0) is not modelled: such surfaces stay opaque.
std::string transparency_warning(const std::string& path, const std::vector<tinyobj::material_t>& materials) {
    std::size_t count = 0;
    std::string first;
    for (const tinyobj::material_t& m : materials) {
        if (!(m.dissolve < 1.0f)) continue;
        if (count++ == 0) first = m.name;
    }
    if (count == 0) return {};
    return path + ": " + std::to_string(count) + " material(s) are partly transparent (d < 1, first '" +
           first + "'); transparency is not modelled, so they are opaque";
}

// One group per (shape, material) pair: `usemtl` runs within an object become surfaces of their own.
class GroupTable {
  public:
    GroupTable(PolygonSoup& soup, const std::vector<Material>& materials)
        : soup_(soup), materials_(materials) {}

    std::uint32_t group(const tinyobj::shape_t& shape, std::size_t shape_index, int material_id) {
        const auto key = std::make_pair(shape_index, material_id);
        if (auto it = index_.find(key); it != index_.end()) return it->second;
        const Material material = material_id >= 0 ? materials_[material_id] : default_material();
        soup_.groups.push_back({group_name(shape, material), material});
        return index_[key] = static_cast<std::uint32_t>(soup_.groups.size() - 1);
    }

  private:
    static std::string group_name(const tinyobj::shape_t& shape, const Material& material) {
        const std::set<int> ids(shape.mesh.material_ids.begin(), shape.mesh.material_ids.end());
        if (shape.name.empty()) return material.name;
        return ids.size() > 1 ? shape.name + "/" + material.name : shape.name;
    }

    PolygonSoup& soup_;
    const std::vector<Material>& materials_;
    std::map<std::pair<std::size_t, int>, std::uint32_t> index_;
};

// A face's texture coordinate indices, or none unless every corner has one.
std::vector<std::uint32_t> texcoord_indices(const tinyobj::mesh_t& mesh, std::size_t offset,
                                            std::size_t corners, std::size_t uv_count) {
    std::vector<std::uint32_t> uv;
    for (std::size_t k = 0; k < corners; ++k) {
        const int t = mesh.indices[offset + k].texcoord_index;
        if (t < 0 || static_cast<std::size_t>(t) >= uv_count) return {};
        uv.push_back(static_cast<std::uint32_t>(t));
    }
    return uv;
}

PolygonSoup to_soup(const std::string& path, const tinyobj::ObjReader& reader, const ObjFacts& facts,
                    const std::vector<Material>& materials, std::vector<std::string>& warnings) {
    PolygonSoup soup;
    soup.source = path;
    const auto& v = reader.GetAttrib().vertices;
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) soup.positions.emplace_back(v[i], v[i + 1], v[i + 2]);

    // OBJ's v runs up from the image's bottom row; ours runs down from its top.
    const auto& vt = reader.GetAttrib().texcoords;
    for (std::size_t i = 0; i + 1 < vt.size(); i += 2) soup.texcoords.emplace_back(vt[i], 1.0 - vt[i + 1]);
    const std::size_t uv_count = soup.texcoords.size();

    GroupTable groups(soup, materials);
    std::size_t without_material = 0;
    const auto& shapes = reader.GetShapes();
    std::size_t face = 0;  // in the file's order, which the shapes keep
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        const tinyobj::mesh_t& mesh = shapes[s].mesh;
        std::size_t offset = 0;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++face) {
            // tinyobjloader's count is the true one modulo 256.
            const std::size_t corners = face < facts.face_corners.size() ? facts.face_corners[face] : 0;
            if (corners % 256 != mesh.num_face_vertices[f] || offset + corners > mesh.indices.size())
                throw InputError(path + ": face " + std::to_string(face + 1) +
                                 " reads differently from its check; the file is not understood");
            const int material_id = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
            if (material_id < 0) ++without_material;
            PolygonSoup::Polygon polygon;
            polygon.group = groups.group(shapes[s], s, material_id);
            for (std::size_t k = 0; k < corners; ++k) {
                polygon.vertices.push_back(static_cast<std::uint32_t>(mesh.indices[offset + k].vertex_index));
            }
            if (soup.groups[polygon.group].material.texture)
                polygon.texcoords = texcoord_indices(mesh, offset, corners, uv_count);
            offset += corners;
            soup.polygons.push_back(std::move(polygon));
        }
    }
    if (facts.short_faces > 0) {
        warnings.push_back(path + ": skipped " + std::to_string(facts.short_faces) +
                           " face(s) of fewer than 3 corners");
    }
    if (without_material > 0) {
        warnings.push_back(path + ": " + std::to_string(without_material) +
                           " face(s) have no material (no usemtl, or a name no .mtl defines); they use the "
                           "default: reflectance 0.5, no emission");
    }
    return soup;
}

}  // namespace

Scene load_obj(const std::string& path) {
    const std::string text = read_text_file(path);
    const ObjFacts facts = check_obj_text(text, path);
    std::vector<std::string> warnings;
    const MaterialLibraries libs = read_material_libraries(path, facts, warnings);

    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // we keep planar convex polygons whole and triangulate the rest ourselves
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, libs.text, config)) {
        throw InputError(path + ": " + first_line(reader.Error()));
    }
    std::vector<Material> materials;
    ReflectanceClamps clamps;
    ObjTextures textures(path);
    for (const auto& m : reader.GetMaterials()) materials.push_back(to_material(m, libs, clamps, textures));
    if (const std::string w = clamps.warning(path); !w.empty()) warnings.push_back(w);
    if (const std::string w = textures.warning(); !w.empty()) warnings.push_back(w);
    if (const std::string w = transparency_warning(path, reader.GetMaterials()); !w.empty())
        warnings.push_back(w);

    Scene scene = build_scene(to_soup(path, reader, facts, materials, warnings));
    scene.warnings.insert(scene.warnings.begin(), warnings.begin(), warnings.end());
    return scene;
}

}  // namespace rad
