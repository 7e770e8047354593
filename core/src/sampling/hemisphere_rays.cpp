#include "sampling/hemisphere_rays.hpp"

#include <limits>
#include <vector>

#include "sampling/bilinear_quad.hpp"
#include "sampling/sampling.hpp"

namespace rad {

void hemisphere_rays(const PatchMesh& patches, std::uint32_t patch, std::uint64_t seed, double offset,
                     std::span<Ray> rays, std::span<double> weights) {
    RandomStream random(seed, patch);
    // Reused from call to call: a pass calls this once per patch on each thread.
    thread_local std::vector<glm::dvec2> origins, directions;
    origins.resize(rays.size());
    directions.resize(rays.size());
    stratified_square(random, origins);
    // Directions stay in stratum order (the origins' shuffle pairs them at random), so consecutive rays run
    // in similar directions, which Embree traces a little faster.
    stratified_square(random, directions, false);

    const glm::uvec4& c = patches.corners[patch];
    const Patch& p = patches.patches[patch];
    const BilinearQuad quad{patches.points[c[0]], patches.points[c[1]], patches.points[c[2]],
                            patches.points[c[3]]};
    const bool triangle = patches.is_triangle(patch);
    const Frame frame = frame_around(p.normal);
    const glm::dvec3 lift = offset * p.normal;
    for (std::size_t k = 0; k < rays.size(); ++k) {
        glm::dvec3 origin;
        if (triangle) {
            origin = point_on_triangle(quad.a, quad.b, quad.c, origins[k]);
            weights[k] = 1.0;
        } else {
            origin = quad.point(origins[k]);
            weights[k] = quad.jacobian(origins[k]) / p.area;
        }
        rays[k].origin = origin + lift;
        rays[k].tnear = 0.0f;
        rays[k].direction = frame.to_world(cosine_direction(directions[k]));
        rays[k].tfar = std::numeric_limits<float>::infinity();
    }
}

}  // namespace rad
