#include "sampling/sampling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

namespace rad {

namespace {

std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ull;

}  // namespace

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t key_a, std::uint64_t key_b)
    : state_(mix(mix(mix(seed) + key_a * kGolden) + key_b * kGolden)) {}

RandomStream::result_type RandomStream::operator()() {
    state_ += kGolden;
    return mix(state_);
}

double RandomStream::uniform() {
    return static_cast<double>((*this)() >> 11) * 0x1.0p-53;
}

void stratified_square(RandomStream& random, std::span<glm::dvec2> points, bool shuffled) {
    const auto m = static_cast<std::size_t>(std::sqrt(static_cast<double>(points.size())));
    const double cell = m > 0 ? 1.0 / static_cast<double>(m) : 1.0;
    std::size_t k = 0;
    for (std::size_t y = 0; y < m; ++y) {
        for (std::size_t x = 0; x < m; ++x, ++k) {
            points[k] = {(static_cast<double>(x) + random.uniform()) * cell,
                         (static_cast<double>(y) + random.uniform()) * cell};
        }
    }
    for (; k < points.size(); ++k) points[k] = {random.uniform(), random.uniform()};
    if (shuffled) std::shuffle(points.begin(), points.end(), random);
}

glm::dvec3 cosine_direction(const glm::dvec2& u) {
    const double a = 2.0 * u.x - 1.0;
    const double b = 2.0 * u.y - 1.0;
    double r = 0.0;
    double phi = 0.0;
    if (a != 0.0 || b != 0.0) {
        constexpr double kQuarterPi = std::numbers::pi / 4.0;
        if (std::abs(a) > std::abs(b)) {
            r = a;
            phi = kQuarterPi * (b / a);
        } else {
            r = b;
            phi = 2.0 * kQuarterPi - kQuarterPi * (a / b);
        }
    }
    // Float trigonometry: the direction goes to Embree in float anyway, and it is twice as fast.
    const double x = r * static_cast<double>(std::cos(static_cast<float>(phi)));
    const double y = r * static_cast<double>(std::sin(static_cast<float>(phi)));
    return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}

Frame frame_around(const glm::dvec3& n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    return {{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
}

glm::dvec3 point_on_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                             const glm::dvec2& u) {
    const double s = std::sqrt(u.x);
    return (1.0 - s) * a + s * (1.0 - u.y) * b + s * u.y * c;
}

glm::dvec3 point_on_convex_polygon(std::span<const glm::dvec3> polygon, glm::dvec2 u) {
    std::array<double, kMaxPolygonCorners - 2> areas{};
    const std::size_t triangles = std::min(polygon.size(), kMaxPolygonCorners) - 2;
    double total = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        areas[t] = glm::length(glm::cross(polygon[t + 1] - polygon[0], polygon[t + 2] - polygon[0]));
        total += areas[t];
    }
    double pick = u.x * total;
    std::size_t t = 0;
    while (t + 1 < triangles && pick >= areas[t]) pick -= areas[t++];
    u.x = areas[t] > 0.0 ? std::clamp(pick / areas[t], 0.0, 1.0) : 0.0;
    return point_on_triangle(polygon[0], polygon[t + 1], polygon[t + 2], u);
}

}  // namespace rad
