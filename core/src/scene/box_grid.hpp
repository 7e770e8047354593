#pragma once

// A uniform grid over polygons' bounding boxes, to find the polygons near another. Private to the library.

#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

#include "rad/scene/scene.hpp"

namespace rad {

class BoxGrid {
  public:
    // `polygons` holds each polygon's corners (empty ones are left out); `bounds` holds them all.
    BoxGrid(const std::vector<std::vector<glm::dvec3>>& polygons, const BoundingBox& bounds);

    // The polygons whose boxes meet the box of `points` grown by `margin`, each once, in `out`.
    void query(const std::vector<glm::dvec3>& points, double margin, std::vector<std::uint32_t>& out) const;

  private:
    struct CellRange {
        glm::ivec3 lo, hi;
        std::size_t count() const;
    };
    CellRange range(glm::dvec3 lo, glm::dvec3 hi) const;
    std::uint64_t key(int x, int y, int z) const;

    std::vector<glm::dvec3> lower_, upper_;  // per polygon
    glm::dvec3 origin_{0.0};
    double cell_ = 1.0;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
    std::vector<std::uint32_t> large_;  // polygons over too many cells, met by every query
    mutable std::vector<std::uint32_t> stamp_;
    mutable std::uint32_t query_ = 0;
};

}  // namespace rad
