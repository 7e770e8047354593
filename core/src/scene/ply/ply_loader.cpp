// OpenMesh's IO header must come before any mesh header.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cmath>
#include <map>
#include <sstream>

#include "rad/scene/polygon_soup.hpp"
#include "rad/scene/scene_loader.hpp"
#include "rad/util/error.hpp"
#include "scene/ply/ply_check.hpp"
#include "scene/text_file.hpp"

namespace rad {

namespace {

struct PlyTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Color = OpenMesh::Vec3f;  // OpenMesh scales 8-bit colours to [0, 1]
};
using PlyMesh = OpenMesh::PolyMesh_ArrayKernelT<PlyTraits>;

// check_ply has already refused malformed files, so OpenMesh's own complaints (on its error stream) would
// only repeat ours, and its log names every header word it skips ("Unsupported keyword"); keep the terminal
// clean while it reads. (Redirecting the streams instead leaks in OpenMesh 9's mostream.)
class QuietOpenMesh {
  public:
    QuietOpenMesh() {
        omerr().disable();
        omlog().disable();
    }
    ~QuietOpenMesh() {
        omerr().enable();
        omlog().enable();
    }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;
};

// `repaired`: the bytes to read instead of the file (check_ply's), or empty.
PlyMesh read_ply_mesh(const std::string& path, const std::string& repaired, bool& has_face_colors,
                      bool& has_vertex_colors) {
    PlyMesh mesh;
    mesh.request_vertex_colors();
    mesh.request_face_colors();
    OpenMesh::IO::Options options = OpenMesh::IO::Options::VertexColor | OpenMesh::IO::Options::FaceColor;
    const QuietOpenMesh quiet;
    bool read = false;
    if (repaired.empty()) {
        read = OpenMesh::IO::read_mesh(mesh, path, options);
    } else {
        std::istringstream in(repaired, std::ios::binary);
        read = OpenMesh::IO::read_mesh(mesh, in, ".ply", options);
    }
    if (!read) throw InputError(path + ": OpenMesh could not read this PLY file");
    has_face_colors = options.face_has_color();
    has_vertex_colors = options.vertex_has_color();
    return mesh;
}

OpenMesh::Vec3f face_colour(const PlyMesh& mesh, PlyMesh::FaceHandle f, bool face_colors) {
    if (face_colors) return mesh.color(f);
    OpenMesh::Vec3f sum(0.0f);
    int count = 0;
    for (auto v : mesh.fv_range(f)) {
        sum += mesh.color(v);
        ++count;
    }
    return count > 0 ? sum / static_cast<float>(count) : sum;
}

// Faces of one colour become one surface whose reflectance is that colour.
PolygonSoup to_soup(const std::string& path, const PlyMesh& mesh, bool face_colors, bool vertex_colors,
                    ReflectanceClamps& clamps) {
    PolygonSoup soup;
    soup.source = path;
    for (auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            throw InputError(path + ": vertex " + std::to_string(v.idx()) +
                             " has a coordinate that is not finite");
        }
        soup.positions.emplace_back(p[0], p[1], p[2]);
    }
    const bool coloured = face_colors || vertex_colors;
    if (!coloured) soup.groups.push_back({"mesh", default_material()});
    std::map<std::array<int, 3>, std::uint32_t> group_of_colour;
    for (auto f : mesh.faces()) {
        PolygonSoup::Polygon polygon;
        for (auto v : mesh.fv_range(f)) polygon.vertices.push_back(static_cast<std::uint32_t>(v.idx()));
        if (coloured) {
            const OpenMesh::Vec3f c = face_colour(mesh, f, face_colors);
            const std::array<int, 3> key{int(std::lround(c[0] * 255)), int(std::lround(c[1] * 255)),
                                         int(std::lround(c[2] * 255))};
            auto [it, added] =
                group_of_colour.try_emplace(key, static_cast<std::uint32_t>(soup.groups.size()));
            if (added) {
                Material m;
                m.name = "colour " + std::to_string(key[0]) + " " + std::to_string(key[1]) + " " +
                         std::to_string(key[2]);
                m.reflectance = glm::dvec3(key[0], key[1], key[2]) / 255.0;
                clamps.clamp(m);  // white is 255, or a float colour of 1
                validate_material(m, path + ": face " + std::to_string(f.idx()));
                soup.groups.push_back({m.name, m});
            }
            polygon.group = it->second;
        }
        soup.polygons.push_back(std::move(polygon));
    }
    return soup;
}

}  // namespace

Scene load_ply(const std::string& path) {
    const PlyCheck check = check_ply(path, read_text_file(path));
    bool face_colors = false;
    bool vertex_colors = false;
    const PlyMesh mesh = read_ply_mesh(path, check.repaired, face_colors, vertex_colors);
    ReflectanceClamps clamps;
    Scene scene = build_scene(to_soup(path, mesh, face_colors, vertex_colors, clamps));
    if (check.skipped_faces > 0) {
        scene.warnings.insert(scene.warnings.begin(),
                              path + ": skipped " + std::to_string(check.skipped_faces) +
                                  " face(s) of fewer than 3 corners or with a corner repeated");
    }
    if (const std::string w = clamps.warning(path); !w.empty())
        scene.warnings.insert(scene.warnings.begin(), w);
    if (!face_colors && !vertex_colors) {
        scene.warnings.insert(scene.warnings.begin(),
                              path + ": no colours; every face uses the default material (reflectance 0.5)");
    }
    return scene;
}

}  // namespace rad
