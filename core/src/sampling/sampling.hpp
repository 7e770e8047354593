#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>

#include "rad/geometry/point_polygon_factor.hpp"

namespace rad {

// A random stream that depends only on the numbers it was made from (the seed and, say, a patch index),
// never on the thread that draws from it: SplitMix64 (Steele, Lea and Flood 2014) over a hash of the keys.
class RandomStream {
  public:
    using result_type = std::uint64_t;

    RandomStream(std::uint64_t seed, std::uint64_t key_a, std::uint64_t key_b = 0);

    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
    result_type operator()();
    // Uniform in [0, 1).
    double uniform();

  private:
    std::uint64_t state_;
};

// points.size() points in the unit square, jittered on the largest m x m grid that fits (m = floor(sqrt(n)));
// the n - m² points left over are uniform. Shuffled unless asked not to: pairing a shuffled set with another
// set pairs their strata at random, without correlation.
void stratified_square(RandomStream& random, std::span<glm::dvec2> points, bool shuffled = true);

// A cosine-weighted direction around +z from a point of the unit square (Malley's method: Shirley and Chiu's
// concentric map to the disk, lifted to the hemisphere), so strata of the square stay strata of directions.
glm::dvec3 cosine_direction(const glm::dvec2& u);

// An orthonormal frame whose third axis is the unit vector n (Duff et al. 2017).
struct Frame {
    glm::dvec3 tangent, bitangent, normal;
    glm::dvec3 to_world(const glm::dvec3& local) const {
        return local.x * tangent + local.y * bitangent + local.z * normal;
    }
};
Frame frame_around(const glm::dvec3& n);

// Area-uniform map of the unit square onto the triangle abc that keeps strata compact.
glm::dvec3 point_on_triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                             const glm::dvec2& u);

// Area-uniform point of a convex polygon of at most kMaxPolygonCorners corners (fanned from its first
// corner): u.x picks the triangle by area.
glm::dvec3 point_on_convex_polygon(std::span<const glm::dvec3> polygon, glm::dvec2 u);

}  // namespace rad
