#pragma once

// Scenes with known form factors, the closed forms of docs/analytic.md, and a way to add up
// patch-to-patch factors into surface-to-surface ones. Header-only: each test program is one source file.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "rad/mesh/patch_mesh.hpp"
#include "rad/scene/polygon_soup.hpp"
#include "rad/transport/uniform/form_factor_matrix.hpp"

namespace rad::test {

// Builds a scene from named one-polygon surfaces, each listed counter-clockwise seen from its front.
class TestSceneBuilder {
  public:
    TestSceneBuilder& add(const std::string& name, std::initializer_list<glm::dvec3> corners) {
        soup_.groups.push_back({name, Material{name, glm::dvec3(0.5), glm::dvec3(0.0)}});
        PolygonSoup::Polygon polygon;
        polygon.group = static_cast<std::uint32_t>(soup_.groups.size() - 1);
        for (const glm::dvec3& p : corners) {
            soup_.positions.push_back(p);
            polygon.vertices.push_back(static_cast<std::uint32_t>(soup_.positions.size() - 1));
        }
        soup_.polygons.push_back(polygon);
        return *this;
    }
    Scene build() {
        soup_.source = "test";
        return build_scene(soup_);
    }

  private:
    PolygonSoup soup_;
};

// Surface 0: a × b at y = 0 facing up; surface 1: the same at y = c facing down, directly opposed.
inline Scene parallel_rectangles(double a, double b, double c) {
    return TestSceneBuilder()
        .add("lower", {{0, 0, 0}, {0, 0, b}, {a, 0, b}, {a, 0, 0}})
        .add("upper", {{0, c, 0}, {a, c, 0}, {a, c, b}, {0, c, b}})
        .build();
}

// Surface 0: the floor, w (along x) by l (along z), facing up; surface 1: the wall x = 0, h high, facing +x.
// They share the edge of length l.
inline Scene perpendicular_rectangles(double w, double h, double l) {
    return TestSceneBuilder()
        .add("floor", {{0, 0, 0}, {0, 0, l}, {w, 0, l}, {w, 0, 0}})
        .add("wall", {{0, 0, 0}, {0, h, 0}, {0, h, l}, {0, 0, l}})
        .build();
}

// docs/analytic.md: parallel, directly opposed rectangles a × b at distance c.
inline double parallel_rectangles_factor(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double x1 = std::sqrt(1 + x * x), y1 = std::sqrt(1 + y * y);
    return 2.0 / (std::numbers::pi * x * y) *
           (std::log(x1 * y1 / std::sqrt(1 + x * x + y * y)) + x * y1 * std::atan(x / y1) +
            y * x1 * std::atan(y / x1) - x * std::atan(x) - y * std::atan(y));
}

// docs/analytic.md: perpendicular rectangles sharing an edge of length l; from A1 (width w) to A2 (height h).
inline double perpendicular_rectangles_factor(double w, double h, double l) {
    const double W = w / l, H = h / l;
    const double W2 = W * W, H2 = H * H, S = std::sqrt(W2 + H2);
    const double log_term = std::log((1 + W2) * (1 + H2) / (1 + W2 + H2)) +
                            W2 * std::log(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2))) +
                            H2 * std::log(H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2)));
    return 1.0 / (std::numbers::pi * W) *
           (W * std::atan(1 / W) + H * std::atan(1 / H) - S * std::atan(1 / S) + 0.25 * log_term);
}

// F from surface s to surface t: Σ_{i in s} A_i Σ_{j in t} F_ij / A_s.
inline double surface_factor(const FormFactorMatrix& f, const PatchMesh& mesh, std::uint32_t s,
                             std::uint32_t t) {
    double energy = 0.0, area = 0.0;
    for (std::uint32_t i = mesh.surface_begin[s]; i < mesh.surface_begin[s + 1]; ++i) {
        area += mesh.patches[i].area;
        const FormFactorRow row = f.row(i);
        for (std::size_t k = 0; k < row.size(); ++k) {
            const std::uint32_t j = row.columns[k];
            if (j >= mesh.surface_begin[t] && j < mesh.surface_begin[t + 1])
                energy += mesh.patches[i].area * row.values[k];
        }
    }
    return energy / area;
}

inline PatchMesh mesh(const Scene& scene, double patch_size) {
    MeshingOptions options;
    options.patch_size = patch_size;
    return build_patches(scene, options);
}

// The configurations of docs/analytic.md with their tabulated form factors.
struct Configuration {
    std::string name;
    bool perpendicular = false;
    double a = 1, b = 1, c = 1;  // parallel: a × b at distance c; perpendicular: w, h, l
    double table_value = 0.0;    // from docs/analytic.md

    Scene scene() const {
        return perpendicular ? perpendicular_rectangles(a, b, c) : parallel_rectangles(a, b, c);
    }
    double closed_form() const {
        return perpendicular ? perpendicular_rectangles_factor(a, b, c) : parallel_rectangles_factor(a, b, c);
    }
    double longest_side() const { return std::max({a, b, c}); }
};

inline std::ostream& operator<<(std::ostream& out, const Configuration& c) {
    return out << c.name;
}

inline const std::vector<Configuration>& configurations() {
    static const std::vector<Configuration> all = {
        {"parallel_1x1_at_1", false, 1, 1, 1, 0.199825},
        {"parallel_1x1_at_0_5", false, 1, 1, 0.5, 0.415253},
        {"parallel_1x1_at_2", false, 1, 1, 2, 0.068590},
        {"parallel_1x1_5_at_0_5", false, 1, 1.5, 0.5, 0.475576},
        {"perpendicular_1_1_1", true, 1, 1, 1, 0.200044},
        {"perpendicular_1_1_0_5", true, 1, 1, 0.5, 0.149300},
        {"perpendicular_1_2_1", true, 1, 2, 1, 0.232853},
    };
    return all;
}

inline std::string configuration_name(const testing::TestParamInfo<Configuration>& info) {
    return info.param.name;
}

}  // namespace rad::test
