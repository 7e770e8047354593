#include "rad/mesh/patch_mesh.hpp"

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <sstream>
#include <unordered_map>

#include "rad/geometry/polygon.hpp"
#include "rad/util/error.hpp"

namespace rad {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A face ready to be gridded: a triangle or a quad (n > 4 polygons are fanned around their centroid).
struct Element {
    std::array<std::uint32_t, 4> v{};     // layout vertices, counter-clockwise
    std::array<std::uint32_t, 4> edge{};  // edge[i] joins v[i] and v[(i + 1) % count]
    int count = 3;
    glm::dvec3 normal{0.0};
    std::uint32_t face = 0;  // in the surface's mesh
};

// One surface's faces as elements, and how many segments each edge is cut into. Opposite edges of a quad
// and all edges of a triangle must have the same count for a regular grid, and an edge shared by two
// elements has one count, so counts are unified over classes of edges (union-find), each class taking the
// count its longest member needs.
struct SurfaceLayout {
    std::vector<glm::dvec3> vertex;
    std::vector<Element> elements;
    std::vector<std::array<std::uint32_t, 2>> edges;  // (low, high) vertex
    std::vector<double> segments;                     // per edge; double so huge counts cannot overflow
};

class EdgeClasses {
  public:
    std::uint32_t add() {
        parent_.push_back(static_cast<std::uint32_t>(parent_.size()));
        return parent_.back();
    }
    std::uint32_t find(std::uint32_t e) {
        while (parent_[e] != e) e = parent_[e] = parent_[parent_[e]];
        return e;
    }
    void unite(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

  private:
    std::vector<std::uint32_t> parent_;
};

class LayoutBuilder {
  public:
    LayoutBuilder(const SurfaceMesh& mesh, double patch_size) : patch_size_(patch_size) {
        for (auto v : mesh.vertices()) layout_.vertex.push_back(to_glm(mesh.point(v)));
        for (auto f : mesh.faces()) add_face(mesh, f);
    }

    SurfaceLayout finish() {
        std::vector<double> class_segments(layout_.edges.size(), 1.0);
        for (std::uint32_t e = 0; e < layout_.edges.size(); ++e) {
            const auto [a, b] = layout_.edges[e];
            const double length = glm::length(layout_.vertex[b] - layout_.vertex[a]);
            double& s = class_segments[classes_.find(e)];
            s = std::max(s, std::ceil(length / patch_size_));
        }
        layout_.segments.resize(layout_.edges.size());
        for (std::uint32_t e = 0; e < layout_.edges.size(); ++e) {
            layout_.segments[e] = class_segments[classes_.find(e)];
        }
        return std::move(layout_);
    }

  private:
    void add_face(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle f) {
        std::vector<std::uint32_t> corners;
        std::vector<glm::dvec3> points;
        for (auto v : mesh.fv_range(f)) {
            corners.push_back(static_cast<std::uint32_t>(v.idx()));
            points.push_back(layout_.vertex[corners.back()]);
        }
        const glm::dvec3 normal = glm::normalize(newell_normal(points));
        const auto face = static_cast<std::uint32_t>(f.idx());
        if (corners.size() <= 4) {
            add_element(corners, normal, face);
            return;
        }
        glm::dvec3 centre(0.0);
        for (const auto& p : points) centre += p;
        layout_.vertex.push_back(centre / static_cast<double>(points.size()));
        const auto c = static_cast<std::uint32_t>(layout_.vertex.size() - 1);
        for (std::size_t i = 0; i < corners.size(); ++i) {
            add_element({corners[i], corners[(i + 1) % corners.size()], c}, normal, face);
        }
    }

    void add_element(const std::vector<std::uint32_t>& corners, const glm::dvec3& normal,
                     std::uint32_t face) {
        Element e;
        e.count = static_cast<int>(corners.size());
        e.normal = normal;
        e.face = face;
        for (int i = 0; i < e.count; ++i) {
            e.v[i] = corners[i];
            e.edge[i] = edge_between(corners[i], corners[(i + 1) % e.count]);
        }
        if (e.count == 4) {
            classes_.unite(e.edge[0], e.edge[2]);
            classes_.unite(e.edge[1], e.edge[3]);
        } else {
            classes_.unite(e.edge[0], e.edge[1]);
            classes_.unite(e.edge[1], e.edge[2]);
        }
        layout_.elements.push_back(e);
    }

    std::uint32_t edge_between(std::uint32_t a, std::uint32_t b) {
        const std::uint32_t lo = std::min(a, b);
        const std::uint32_t hi = std::max(a, b);
        const std::uint64_t key = (std::uint64_t{lo} << 32) | hi;
        auto [it, inserted] = edge_index_.try_emplace(key, static_cast<std::uint32_t>(layout_.edges.size()));
        if (inserted) {
            layout_.edges.push_back({lo, hi});
            classes_.add();
        }
        return it->second;
    }

    double patch_size_;
    SurfaceLayout layout_;
    EdgeClasses classes_;
    std::unordered_map<std::uint64_t, std::uint32_t> edge_index_;
};

double patch_count(const SurfaceLayout& layout) {
    double count = 0.0;
    for (const Element& e : layout.elements) {
        const double n = layout.segments[e.edge[0]];
        count += e.count == 4 ? n * layout.segments[e.edge[1]] : n * n;
    }
    return count;
}

// Emits one surface's patches into the PatchMesh, creating each corner once so the grid conforms.
class SurfaceGridder {
  public:
    SurfaceGridder(const SurfaceLayout& layout, std::uint32_t surface, PatchMesh& out)
        : layout_(layout),
          surface_(surface),
          out_(out),
          vertex_point_(layout.vertex.size(), kNone),
          edge_first_point_(layout.edges.size(), kNone) {}

    void run() {
        for (const Element& e : layout_.elements) {
            if (e.count == 4) {
                grid_quad(e);
            } else {
                grid_triangle(e);
            }
        }
    }

  private:
    std::uint32_t new_point(const glm::dvec3& p) {
        out_.points.push_back(p);
        return static_cast<std::uint32_t>(out_.points.size() - 1);
    }

    std::uint32_t corner_point(std::uint32_t v) {
        if (vertex_point_[v] == kNone) vertex_point_[v] = new_point(layout_.vertex[v]);
        return vertex_point_[v];
    }

    // The k-th of the n + 1 points from vertex `from` along edge `e` (k = 0 is `from` itself).
    std::uint32_t edge_point(std::uint32_t e, std::uint32_t from, std::uint32_t k) {
        const auto [lo, hi] = layout_.edges[e];
        const auto n = static_cast<std::uint32_t>(layout_.segments[e]);
        const std::uint32_t k_from_lo = (from == lo) ? k : n - k;
        if (k_from_lo == 0) return corner_point(lo);
        if (k_from_lo == n) return corner_point(hi);
        if (edge_first_point_[e] == kNone) {
            const glm::dvec3 a = layout_.vertex[lo];
            const glm::dvec3 b = layout_.vertex[hi];
            edge_first_point_[e] = static_cast<std::uint32_t>(out_.points.size());
            for (std::uint32_t i = 1; i < n; ++i) new_point(a + (b - a) * (double(i) / n));
        }
        return edge_first_point_[e] + k_from_lo - 1;
    }

    void grid_quad(const Element& e) {
        const auto n = static_cast<std::uint32_t>(layout_.segments[e.edge[0]]);
        const auto m = static_cast<std::uint32_t>(layout_.segments[e.edge[1]]);
        const glm::dvec3 &a = layout_.vertex[e.v[0]], &b = layout_.vertex[e.v[1]];
        const glm::dvec3 &c = layout_.vertex[e.v[2]], &d = layout_.vertex[e.v[3]];
        std::vector<std::uint32_t> grid((n + 1) * (m + 1));
        auto at = [&](std::uint32_t i, std::uint32_t j) -> std::uint32_t& { return grid[j * (n + 1) + i]; };
        for (std::uint32_t j = 0; j <= m; ++j) {
            for (std::uint32_t i = 0; i <= n; ++i) {
                if (j == 0) {
                    at(i, j) = edge_point(e.edge[0], e.v[0], i);
                } else if (j == m) {
                    at(i, j) = edge_point(e.edge[2], e.v[3], i);
                } else if (i == 0) {
                    at(i, j) = edge_point(e.edge[3], e.v[0], j);
                } else if (i == n) {
                    at(i, j) = edge_point(e.edge[1], e.v[1], j);
                } else {
                    const double u = double(i) / n, v = double(j) / m;
                    at(i, j) =
                        new_point((1 - u) * (1 - v) * a + u * (1 - v) * b + u * v * c + (1 - u) * v * d);
                }
            }
        }
        for (std::uint32_t j = 0; j < m; ++j) {
            for (std::uint32_t i = 0; i < n; ++i) {
                add_patch({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, e);
            }
        }
    }

    void grid_triangle(const Element& e) {
        const auto n = static_cast<std::uint32_t>(layout_.segments[e.edge[0]]);
        const glm::dvec3 &a = layout_.vertex[e.v[0]], &b = layout_.vertex[e.v[1]],
                         &c = layout_.vertex[e.v[2]];
        // Row j holds points i = 0 .. n - j, from edge v0-v2 (i = 0) to edge v1-v2 (i = n - j).
        std::vector<std::uint32_t> grid((n + 1) * (n + 2) / 2);
        std::vector<std::uint32_t> row_start(n + 1);
        for (std::uint32_t j = 0, s = 0; j <= n; s += n + 1 - j, ++j) row_start[j] = s;
        auto at = [&](std::uint32_t i, std::uint32_t j) -> std::uint32_t& { return grid[row_start[j] + i]; };
        for (std::uint32_t j = 0; j <= n; ++j) {
            for (std::uint32_t i = 0; i + j <= n; ++i) {
                if (j == 0) {
                    at(i, j) = edge_point(e.edge[0], e.v[0], i);
                } else if (i == 0) {
                    at(i, j) = edge_point(e.edge[2], e.v[0], j);
                } else if (i + j == n) {
                    at(i, j) = edge_point(e.edge[1], e.v[1], j);
                } else {
                    at(i, j) = new_point(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n));
                }
            }
        }
        for (std::uint32_t j = 0; j < n; ++j) {
            for (std::uint32_t i = 0; i + j < n; ++i) {
                add_patch({at(i, j), at(i + 1, j), at(i, j + 1), at(i, j + 1)}, e);
                if (i + j + 1 < n) add_patch({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), at(i, j + 1)}, e);
            }
        }
    }

    void add_patch(const glm::uvec4& c, const Element& e) {
        out_.corners.push_back(c);
        out_.patches.push_back(measure_patch(out_.points, c, surface_, e.normal));
        out_.patches.back().face = e.face;
    }

    const SurfaceLayout& layout_;
    std::uint32_t surface_;
    PatchMesh& out_;
    std::vector<std::uint32_t> vertex_point_;
    std::vector<std::uint32_t> edge_first_point_;
};

double checked_patch_size(const Scene& scene, double requested) {
    if (requested == 0.0) return default_patch_size(scene);
    if (!std::isfinite(requested) || requested < 0.0) {
        throw SettingError("patch_size", "must be a positive number of scene units");
    }
    return requested;
}

std::vector<SurfaceLayout> layout_scene(const Scene& scene, double patch_size) {
    std::vector<SurfaceLayout> layouts;
    layouts.reserve(scene.surfaces.size());
    for (const Surface& s : scene.surfaces) layouts.push_back(LayoutBuilder(s.mesh, patch_size).finish());
    return layouts;
}

double total_patch_count(const std::vector<SurfaceLayout>& layouts) {
    double count = 0.0;
    for (const auto& l : layouts) count += patch_count(l);
    return count;
}

// Patch count scales about as 1/size², but edges are cut into whole segments, so check the guess and
// grow it until it really fits.
double patch_size_that_fits(const Scene& scene, double patch_size, double count, std::size_t max_patches) {
    double size = patch_size * std::sqrt(count / static_cast<double>(max_patches));
    for (int tries = 0; tries < 64; ++tries) {
        if (total_patch_count(layout_scene(scene, size)) <= static_cast<double>(max_patches)) break;
        size *= 1.05;
    }
    // Round up to three significant digits, so the printed value is at least the one checked.
    const double step = std::pow(10.0, std::floor(std::log10(size)) - 2.0);
    return std::ceil(size / step) * step;
}

}  // namespace

Patch measure_patch(std::span<const glm::dvec3> points, const glm::uvec4& c, std::uint32_t surface,
                    const glm::dvec3& normal) {
    const glm::dvec3 &p0 = points[c[0]], &p1 = points[c[1]];
    const glm::dvec3 &p2 = points[c[2]], &p3 = points[c[3]];
    Patch patch;
    patch.surface = surface;
    patch.normal = normal;
    const double a012 = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    const double a023 = 0.5 * glm::length(glm::cross(p2 - p0, p3 - p0));
    patch.area = a012 + a023;
    patch.centroid = patch.area > 0.0 ? (a012 * (p0 + p1 + p2) + a023 * (p0 + p2 + p3)) / (3.0 * patch.area)
                                      : (p0 + p1 + p2) / 3.0;
    return patch;
}

std::vector<std::uint8_t> back_to_back_surfaces(const Scene& scene) {
    std::vector<std::uint8_t> flags(scene.surfaces.size(), 0);
    bool any = false;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        flags[s] = scene.surfaces[s].back_to_back ? 1 : 0;
        any = any || flags[s] != 0;
    }
    if (!any) flags.clear();
    return flags;
}

double default_patch_size(const Scene& scene) {
    const double extent = bounding_box(scene).largest_extent();
    return extent > 0.0 ? extent / 16.0 : 1.0;
}

std::size_t count_patches(const Scene& scene, double patch_size) {
    const double count = total_patch_count(layout_scene(scene, checked_patch_size(scene, patch_size)));
    return count >= 1e18 ? std::numeric_limits<std::size_t>::max() : static_cast<std::size_t>(count);
}

PatchMesh build_patches(const Scene& scene, const MeshingOptions& options) {
    const double patch_size = checked_patch_size(scene, options.patch_size);
    const std::vector<SurfaceLayout> layouts = layout_scene(scene, patch_size);
    const double count = total_patch_count(layouts);
    if (count > static_cast<double>(options.max_patches)) {
        const double fits = patch_size_that_fits(scene, patch_size, count, options.max_patches);
        std::ostringstream msg;
        msg << patch_size << " would make " << count << " patches, more than the limit of "
            << options.max_patches << "; use {patch_size} " << fits << " or larger";
        throw SettingError("patch_size", msg.str());
    }

    PatchMesh mesh;
    mesh.patches.reserve(static_cast<std::size_t>(count));
    mesh.corners.reserve(static_cast<std::size_t>(count));
    mesh.surface_begin.push_back(0);
    for (std::uint32_t s = 0; s < layouts.size(); ++s) {
        SurfaceGridder(layouts[s], s, mesh).run();
        mesh.surface_begin.push_back(static_cast<std::uint32_t>(mesh.patches.size()));
    }
    mesh.positions.reserve(mesh.points.size());
    for (const auto& p : mesh.points) mesh.positions.emplace_back(p);
    mesh.back_to_back = back_to_back_surfaces(scene);
    return mesh;
}

}  // namespace rad
