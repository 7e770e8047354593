#include "rad/scene/texture.hpp"

#include <cmath>

#include "rad/util/srgb.hpp"

namespace rad {

namespace {

// Texel index along a side of n texels for a coordinate measured in texels, repeating.
int wrap(long long i, int n) {
    const long long m = i % n;
    return static_cast<int>(m < 0 ? m + n : m);
}

}  // namespace

glm::dvec3 Texture::linear_at(const glm::dvec2& uv) const {
    if (width <= 0 || height <= 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y)) return mean;
    // Texel centres lie at half-integers; keep the coordinate's whole part small before converting.
    const double x = (uv.x - std::floor(uv.x)) * width - 0.5;
    const double y = (uv.y - std::floor(uv.y)) * height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const auto texel = [&](long long i, long long j) {
        const std::size_t at = (static_cast<std::size_t>(wrap(j, height)) * width + wrap(i, width)) * 3;
        return glm::dvec3(srgb_byte_to_linear(srgb[at]), srgb_byte_to_linear(srgb[at + 1]),
                          srgb_byte_to_linear(srgb[at + 2]));
    };
    const auto i = static_cast<long long>(fx), j = static_cast<long long>(fy);
    return (1 - ty) * ((1 - tx) * texel(i, j) + tx * texel(i + 1, j)) +
           ty * ((1 - tx) * texel(i, j + 1) + tx * texel(i + 1, j + 1));
}

glm::dvec3 albedo_scale(const Texture& texture, const glm::dvec3& reflectance) {
    glm::dvec3 scale(0.0);
    for (int c = 0; c < 3; ++c) scale[c] = texture.mean[c] > 0.0 ? reflectance[c] / texture.mean[c] : 0.0;
    return scale;
}

}  // namespace rad
