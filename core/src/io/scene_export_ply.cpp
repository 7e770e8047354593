// The PLY export, written by OpenMesh's PLY writer: binary little endian, vertex positions, normals and
// 8-bit sRGB colours, the linear radiance as three float properties, and triangles.
// OpenMesh's property code copies a default-constructed Vec3uc, whose bytes its constructor leaves unset, and
// GCC 12 at -O3 reports that inside the standard library as -Wmaybe-uninitialized; the values are assigned
// before use. (Float colours avoid it but OpenMesh's exporter cannot convert them to every colour type.)
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
// OpenMesh's IO header must come before any mesh header.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <array>
#include <fstream>
#include <stdexcept>
#include <string>

#include "rad/io/scene_export.hpp"
#include "rad/util/srgb.hpp"

namespace rad {

namespace {

struct ExportTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3f;
    using Normal = OpenMesh::Vec3f;
    using Color = OpenMesh::Vec3uc;
    VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::Color);
};
using ExportMesh = OpenMesh::TriMesh_ArrayKernelT<ExportTraits>;

// The linear radiance as persistent float properties, which OpenMesh's writer adds to each vertex.
class RadianceProperties {
  public:
    explicit RadianceProperties(ExportMesh& mesh) {
        static constexpr std::array<const char*, 3> kNames = {"radiance_r", "radiance_g", "radiance_b"};
        for (int c = 0; c < 3; ++c) {
            mesh.add_property(channel_[c], kNames[c]);
            mesh.property(channel_[c]).set_persistent(true);
        }
    }

    void set(ExportMesh& mesh, ExportMesh::VertexHandle vertex, const glm::vec3& radiance) const {
        for (int c = 0; c < 3; ++c) mesh.property(channel_[c], vertex) = radiance[c];
    }

  private:
    std::array<OpenMesh::VPropHandleT<float>, 3> channel_;
};

class ExportMeshBuilder {
  public:
    ExportMeshBuilder(const DisplayMesh& display, std::span<const glm::vec3> radiance, double exposure)
        : display_(display), radiance_(radiance), exposure_(exposure), properties_(mesh_) {}

    ExportMesh build() {
        for (std::size_t v = 0; v < display_.vertex_count(); ++v) add_vertex(v);
        for (const glm::uvec3& t : display_.triangles) add_triangle(t);
        return std::move(mesh_);
    }

  private:
    ExportMesh::VertexHandle add_vertex(std::size_t v) {
        const glm::vec3& p = display_.positions[v];
        const glm::vec3& n = display_.normals[v];
        const ExportMesh::VertexHandle vertex = mesh_.add_vertex({p.x, p.y, p.z});
        mesh_.set_normal(vertex, {n.x, n.y, n.z});
        const glm::vec3 shown = displayed_value(radiance_[v], exposure_);
        mesh_.set_color(vertex, {srgb_byte(shown.x), srgb_byte(shown.y), srgb_byte(shown.z)});
        properties_.set(mesh_, vertex, radiance_[v]);
        return vertex;
    }

    // OpenMesh's half-edge structure refuses a triangle that would make an edge or a vertex non-manifold
    // (and says so on its error stream, kept quiet as we handle it): such a triangle gets its own copies of
    // its vertices, so every triangle is written.
    void add_triangle(const glm::uvec3& t) {
        const auto handle = [](std::uint32_t v) { return ExportMesh::VertexHandle(static_cast<int>(v)); };
        omerr().disable();
        const bool added = mesh_.add_face(handle(t.x), handle(t.y), handle(t.z)).is_valid();
        omerr().enable();
        if (!added) mesh_.add_face(add_vertex(t.x), add_vertex(t.y), add_vertex(t.z));
    }

    const DisplayMesh& display_;
    std::span<const glm::vec3> radiance_;
    double exposure_;
    ExportMesh mesh_;
    RadianceProperties properties_;
};

}  // namespace

void write_ply_export(const std::filesystem::path& path, const DisplayMesh& mesh,
                      std::span<const glm::vec3> radiance, const ExportOptions& options) {
    const ExportMesh exported = ExportMeshBuilder(mesh, radiance, options.exposure).build();
    const OpenMesh::IO::Options what = OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::LSB |
                                       OpenMesh::IO::Options::VertexNormal |
                                       OpenMesh::IO::Options::VertexColor | OpenMesh::IO::Options::Custom;
    // Through our own stream, so a failed write (a full disk) is seen.
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + path.string());
    if (!OpenMesh::IO::write_mesh(exported, out, "ply", what)) {
        throw std::runtime_error(path.string() + ": OpenMesh could not write the PLY file");
    }
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace rad
