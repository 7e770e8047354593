#include "rad/display/display_outline.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace rad {

std::vector<std::uint32_t> patch_outline(const DisplayMesh& display) {
    // (patch, low vertex, high vertex) -> how many of the patch's triangles have that edge.
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, int> edge_uses;
    for (std::size_t t = 0; t < display.triangles.size(); ++t) {
        const glm::uvec3& tri = display.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = tri[k];
            const std::uint32_t b = tri[(k + 1) % 3];
            ++edge_uses[{display.triangle_patch[t], std::min(a, b), std::max(a, b)}];
        }
    }
    std::vector<std::uint32_t> lines;
    for (const auto& [edge, uses] : edge_uses) {
        if (uses != 1) continue;
        lines.push_back(std::get<1>(edge));
        lines.push_back(std::get<2>(edge));
    }
    return lines;
}

}  // namespace rad
