#pragma once

// A polygon soup's corners as the scene builder reads them. Private to the library.

#include <cstdint>
#include <functional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "rad/scene/polygon_soup.hpp"

namespace rad {

// Hashes a position by its exact coordinates (0 and -0 alike).
struct PositionHash {
    std::size_t operator()(const glm::dvec3& p) const {
        std::size_t h = 0;
        for (int c = 0; c < 3; ++c) h = h * 0x100000001b3ull ^ std::hash<double>{}(p[c] + 0.0);
        return h;
    }
};

// Which of a polygon's corners remain once repeated consecutive ones (same index or same position, as in
// "f 1 2 2 3") are dropped: positions in its vertex list.
std::vector<std::size_t> distinct_corners(const PolygonSoup& soup, const std::vector<std::uint32_t>& in);

// The vertex indices of those corners.
std::vector<std::uint32_t> without_repeats(const PolygonSoup& soup, const std::vector<std::uint32_t>& in);

// A polygon's distinct corners and their texture coordinates (empty where it has none).
struct Corners {
    std::vector<std::uint32_t> vertices;
    std::vector<glm::dvec2> uv;
};
Corners polygon_corners(const PolygonSoup& soup, const PolygonSoup::Polygon& p);

std::vector<glm::dvec3> corner_positions(const PolygonSoup& soup, const std::vector<std::uint32_t>& idx);

// The positions of a polygon's distinct corners, in order.
std::vector<glm::dvec3> polygon_points(const PolygonSoup& soup, std::uint32_t index);

}  // namespace rad
