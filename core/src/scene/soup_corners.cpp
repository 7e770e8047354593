#include "scene/soup_corners.hpp"

#include <algorithm>

namespace rad {

std::vector<std::size_t> distinct_corners(const PolygonSoup& soup, const std::vector<std::uint32_t>& in) {
    std::vector<std::size_t> out;
    out.reserve(in.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
        if (!out.empty() && soup.positions[in[out.back()]] == soup.positions[in[k]]) continue;
        out.push_back(k);
    }
    while (out.size() > 1 && soup.positions[in[out.front()]] == soup.positions[in[out.back()]])
        out.pop_back();
    return out;
}

std::vector<std::uint32_t> without_repeats(const PolygonSoup& soup, const std::vector<std::uint32_t>& in) {
    std::vector<std::uint32_t> out;
    for (std::size_t k : distinct_corners(soup, in)) out.push_back(in[k]);
    return out;
}

Corners polygon_corners(const PolygonSoup& soup, const PolygonSoup::Polygon& p) {
    Corners c;
    const bool has_uv = p.texcoords.size() == p.vertices.size() &&
                        std::all_of(p.texcoords.begin(), p.texcoords.end(),
                                    [&](std::uint32_t t) { return t < soup.texcoords.size(); });
    for (std::size_t k : distinct_corners(soup, p.vertices)) {
        c.vertices.push_back(p.vertices[k]);
        if (has_uv) c.uv.push_back(soup.texcoords[p.texcoords[k]]);
    }
    return c;
}

std::vector<glm::dvec3> corner_positions(const PolygonSoup& soup, const std::vector<std::uint32_t>& idx) {
    std::vector<glm::dvec3> out;
    out.reserve(idx.size());
    for (std::uint32_t v : idx) out.push_back(soup.positions[v]);
    return out;
}

std::vector<glm::dvec3> polygon_points(const PolygonSoup& soup, std::uint32_t index) {
    return corner_positions(soup, without_repeats(soup, soup.polygons[index].vertices));
}

}  // namespace rad
