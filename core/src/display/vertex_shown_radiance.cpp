#include <stdexcept>

#include "rad/display/display_mesh.hpp"

namespace rad {

std::vector<glm::vec3> vertex_shown_radiance(const DisplayMesh& display,
                                             std::span<const glm::vec3> radiance) {
    if (radiance.size() != display.vertex_count())
        throw std::invalid_argument("vertex_shown_radiance: the radiance does not have one entry per vertex");
    std::vector<glm::vec3> shown(radiance.begin(), radiance.end());
    if (display.textured.empty()) return shown;
    std::vector<std::uint8_t> done(display.vertex_count(), 0);
    for (const DisplayMesh::TexturedRange& range : display.textured) {
        for (std::uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t) {
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = display.triangles[t][k];
                if (done[v]) continue;
                done[v] = 1;
                const glm::dvec3 texel = range.texture->linear_at(glm::dvec2(display.texcoords[v]));
                shown[v] = range.emitted_radiance + range.albedo_scale * glm::vec3(texel) * radiance[v];
            }
        }
    }
    return shown;
}

}  // namespace rad
