#include "rad/display/display_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <numbers>
#include <span>
#include <stdexcept>

#include "display/patch_gradients.hpp"
#include "display/patch_texturing.hpp"
#include "display/seam_vertices.hpp"

namespace rad {

namespace {

void add_triangles(const PatchMesh& mesh, std::size_t q, const std::uint32_t* vertex, DisplayMesh& display) {
    const auto patch = static_cast<std::uint32_t>(q);
    display.triangles.emplace_back(vertex[0], vertex[1], vertex[2]);
    display.triangle_patch.push_back(patch);
    if (!mesh.is_triangle(q)) {
        display.triangles.emplace_back(vertex[0], vertex[2], vertex[3]);
        display.triangle_patch.push_back(patch);
    }
}

// Appends a vertex that shows patch q's own value; returns its index.
std::uint32_t add_patch_vertex(const glm::dvec3& position, const glm::vec3& normal, std::uint32_t q,
                               const PatchTexturing& texturing, DisplayMesh& display) {
    const auto vertex = static_cast<std::uint32_t>(display.positions.size());
    if (texturing.any()) display.texcoords.push_back(texturing.texcoord(q, position));
    display.positions.emplace_back(position);
    display.normals.push_back(normal);
    display.weight_patch.push_back(q);
    display.weight.push_back(1.0f);
    display.weight_begin.push_back(static_cast<std::uint32_t>(display.weight.size()));
    return vertex;
}

// A patch with T-vertices on its edges, as a fan from its centroid through every boundary point (`vertex`,
// counter-clockwise), so its triangles meet its smaller neighbours' at those points: no crack in geometry
// or colour. The centre shows the patch's own value, which is also what its gradient gives there.
void add_fan(const PatchMesh& mesh, std::size_t q, std::span<const std::uint32_t> vertex,
             const PatchTexturing& texturing, DisplayMesh& display) {
    const auto patch = static_cast<std::uint32_t>(q);
    const std::uint32_t centre = add_patch_vertex(mesh.patches[q].centroid, glm::vec3(mesh.patches[q].normal),
                                                  patch, texturing, display);
    for (std::size_t k = 0; k < vertex.size(); ++k) {
        display.triangles.emplace_back(centre, vertex[k], vertex[(k + 1) % vertex.size()]);
        display.triangle_patch.push_back(patch);
    }
}

// Flat mode ignores outlines: each patch shows its own constant value, so a T-vertex cannot open a crack
// in colour, and its corners alone cover it.
DisplayMesh build_flat(const PatchMesh& mesh, const PatchTexturing& texturing) {
    DisplayMesh display;
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        std::uint32_t vertex[4];
        for (int k = 0; k < mesh.corner_count(q); ++k) {
            vertex[k] = add_patch_vertex(mesh.points[mesh.corners[q][k]], glm::vec3(mesh.patches[q].normal),
                                         static_cast<std::uint32_t>(q), texturing, display);
        }
        add_triangles(mesh, q, vertex, display);
    }
    return display;
}

// The display vertices at one boundary point: its patches grouped by surface and normal.
class CornerSplitter {
  public:
    // `gradients`: one row per patch for linear reconstruction, or none for the area-weighted average.
    CornerSplitter(const PatchMesh& mesh, double cos_crease, PatchGradients gradients,
                   const PatchTexturing& texturing)
        : mesh_(mesh), cos_crease_(cos_crease), gradients_(std::move(gradients)), texturing_(texturing) {}

    // Groups the patches at `point` and appends one display vertex per group; returns each patch's vertex.
    void split(std::uint32_t point, std::span<const std::uint32_t> patches, DisplayMesh& display,
               std::vector<std::uint32_t>& vertex_of_patch) {
        groups_.clear();
        group_of_.resize(patches.size());
        vertex_of_patch.resize(patches.size());
        for (std::size_t a = 0; a < patches.size(); ++a) {
            const Patch& patch = mesh_.patches[patches[a]];
            const Group mine{patch.surface, patch.normal, texturing_.textured(patches[a]),
                             texturing_.texcoord(patches[a], mesh_.points[point])};
            std::size_t g = 0;
            // Compare with each group's first patch, so a group cannot creep round a curve past the angle.
            while (g < groups_.size() && !joins(groups_[g], mine)) ++g;
            if (g == groups_.size()) groups_.push_back(mine);
            group_of_[a] = g;
        }
        for (std::size_t g = 0; g < groups_.size(); ++g)
            add_vertex(point, patches, g, display, vertex_of_patch);
    }

  private:
    struct Group {
        std::uint32_t surface;
        glm::dvec3 normal;
        bool textured;
        glm::vec2 texcoord;  // faces meeting at a texture seam keep vertices of their own
    };

    bool joins(const Group& group, const Group& patch) const {
        constexpr float kSameTexcoord = 1e-5f;
        return group.surface == patch.surface && glm::dot(group.normal, patch.normal) >= cos_crease_ &&
               group.textured == patch.textured &&
               glm::all(
                   glm::lessThanEqual(glm::abs(group.texcoord - patch.texcoord), glm::vec2(kSameTexcoord)));
    }

    // The vertex of the patches in group g (those a with group_of_[a] == g).
    void add_vertex(std::uint32_t point, std::span<const std::uint32_t> patches, std::size_t g,
                    DisplayMesh& display, std::vector<std::uint32_t>& vertex_of_patch) {
        const auto vertex = static_cast<std::uint32_t>(display.positions.size());
        double area = 0.0;
        glm::dvec3 normal(0.0);
        for (std::size_t a = 0; a < patches.size(); ++a) {
            if (group_of_[a] != g) continue;
            const Patch& patch = mesh_.patches[patches[a]];
            area += patch.area;
            normal += patch.area * patch.normal;
        }
        weights_.clear();
        for (std::size_t a = 0; a < patches.size(); ++a) {
            if (group_of_[a] != g) continue;
            add_patch(patches[a], mesh_.patches[patches[a]].area / area, mesh_.points[point]);
            vertex_of_patch[a] = vertex;
        }
        std::sort(weights_.begin(), weights_.end());
        for (std::size_t k = 0; k < weights_.size(); ++k) {
            double sum = weights_[k].second;
            while (k + 1 < weights_.size() && weights_[k + 1].first == weights_[k].first)
                sum += weights_[++k].second;
            display.weight_patch.push_back(weights_[k].first);
            display.weight.push_back(static_cast<float>(sum));
        }
        display.weight_begin.push_back(static_cast<std::uint32_t>(display.weight.size()));
        display.positions.push_back(mesh_.positions[point]);
        if (texturing_.any()) display.texcoords.push_back(groups_[g].texcoord);
        display.normals.emplace_back(glm::length(normal) > 0.0 ? glm::normalize(normal) : groups_[g].normal);
    }

    // Patch q's share `share` of the vertex at `position`: B_q, extrapolated along q's gradient when known.
    void add_patch(std::uint32_t q, double share, const glm::dvec3& position) {
        weights_.emplace_back(q, share);
        if (gradients_.begin.empty()) return;
        const glm::dvec3 offset = position - mesh_.patches[q].centroid;
        for (std::uint32_t k = gradients_.begin[q]; k < gradients_.begin[q + 1]; ++k) {
            const double w = share * glm::dot(gradients_.coefficient[k], offset);
            weights_.emplace_back(gradients_.neighbour[k], w);
            weights_.emplace_back(q, -w);
        }
    }

    const PatchMesh& mesh_;
    double cos_crease_;
    PatchGradients gradients_;
    const PatchTexturing& texturing_;
    std::vector<Group> groups_;
    std::vector<std::size_t> group_of_;  // per patch at the point, its group
    std::vector<std::pair<std::uint32_t, double>> weights_;
};

// Where patch q's points start in an array holding a value per point of every patch's boundary.
std::size_t boundary_start(const PatchMesh& mesh, std::size_t q) {
    return mesh.outline_begin.empty() ? 4 * q : mesh.outline_begin[q];
}

DisplayMesh build_smooth(const PatchMesh& mesh, double crease_angle_degrees, Reconstruction reconstruction,
                         const PatchTexturing& texturing) {
    const PointPatches at = patches_at_points(mesh);
    DisplayMesh display;
    const double cos_crease = std::cos(crease_angle_degrees * std::numbers::pi / 180.0);
    CornerSplitter splitter(
        mesh, cos_crease,
        reconstruction == Reconstruction::linear ? patch_gradients(mesh, at, cos_crease) : PatchGradients{},
        texturing);
    // The display vertex of each point on each patch's boundary, from boundary_start.
    std::vector<std::uint32_t> boundary_vertex(mesh.outline_begin.empty() ? 4 * mesh.size()
                                                                          : mesh.outline.size());
    std::vector<std::uint32_t> vertex_of_patch;
    for (std::uint32_t p = 0; p < mesh.points.size(); ++p) {
        const std::span<const std::uint32_t> patches = at.at(p);
        splitter.split(p, patches, display, vertex_of_patch);
        for (std::size_t a = 0; a < patches.size(); ++a) {
            const std::uint32_t q = patches[a];
            const std::span<const std::uint32_t> boundary = patch_boundary(mesh, q);
            for (std::size_t k = 0; k < boundary.size(); ++k) {
                if (boundary[k] == p) boundary_vertex[boundary_start(mesh, q) + k] = vertex_of_patch[a];
            }
        }
    }
    for (std::size_t q = 0; q < mesh.size(); ++q) {
        const std::span<const std::uint32_t> vertex(boundary_vertex.data() + boundary_start(mesh, q),
                                                    patch_boundary(mesh, q).size());
        if (vertex.size() > static_cast<std::size_t>(mesh.corner_count(q)))
            add_fan(mesh, q, vertex, texturing, display);
        else
            add_triangles(mesh, q, vertex.data(), display);
    }
    return display;
}

}  // namespace

DisplayMesh build_display_mesh(const PatchMesh& patches, const DisplayOptions& options,
                               const DisplayTexturing& texturing) {
    if (!(options.crease_angle_degrees >= 0.0 && options.crease_angle_degrees <= 180.0)) {
        throw std::invalid_argument("crease angle must lie in [0°, 180°]");
    }
    const PatchTexturing textures(patches, texturing);
    DisplayMesh display =
        options.mode == ColourMode::flat
            ? build_flat(patches, textures)
            : build_smooth(patches, options.crease_angle_degrees, options.reconstruction, textures);
    display.patch_count = patches.size();
    display.patch_surface.reserve(patches.size());
    for (const Patch& p : patches.patches) display.patch_surface.push_back(p.surface);
    close_seams(display);
    textures.finish(display);
    return display;
}

}  // namespace rad
