#include "rad/solve/solution.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "rad/geometry/polygon.hpp"

namespace rad {

namespace {

void check_size(std::size_t size, std::size_t elements, const char* what) {
    if (size != elements) {
        throw std::invalid_argument("the solution does not fit the scene: " + std::to_string(size) + " " +
                                    what + " for " + std::to_string(elements) + " elements");
    }
}

// Whether the element's centre lies in the plane of its face, within a hundredth of the face's size (a face
// as modelled can bend a little out of its plane).
bool lies_on_face(const Patch& patch, const SurfaceMesh& mesh) {
    std::vector<glm::dvec3> polygon;
    for (auto v : mesh.fv_range(mesh.face_handle(static_cast<int>(patch.face))))
        polygon.push_back(to_glm(mesh.point(v)));
    if (polygon.size() < 3) return false;
    const glm::dvec3 newell = newell_normal(polygon);
    const double twice_area = glm::length(newell);
    if (twice_area <= 0.0) return true;  // no plane to tell by
    const glm::dvec3 normal = newell / twice_area;
    double size = 0.0;
    for (const glm::dvec3& p : polygon) size = std::max(size, glm::distance(p, polygon.front()));
    return std::abs(glm::dot(patch.centroid - polygon.front(), normal)) <= 1e-2 * size;
}

}  // namespace

void check_solution_fits(const Scene& scene, const Solution& solution) {
    if (!solution.elements) throw std::invalid_argument("the solution does not fit the scene: no elements");
    const std::size_t n = solution.size();
    check_size(solution.area.size(), n, "areas");
    check_size(solution.reflectance.size(), n, "reflectances");
    check_size(solution.emission.size(), n, "emissions");
    check_size(solution.direct.size(), n, "direct lights");
    check_size(solution.radiosity.size(), n, "radiosities");
    check_size(solution.shown_radiosity.size(), n, "shown radiosities");
    if (!solution.outside.empty()) check_size(solution.outside.size(), n, "outside irradiances");
    for (std::size_t e = 0; e < n; ++e) {
        const Patch& patch = solution.elements->patches[e];
        if (patch.surface >= scene.surfaces.size() ||
            patch.face >= scene.surfaces[patch.surface].mesh.n_faces() ||
            !lies_on_face(patch, scene.surfaces[patch.surface].mesh)) {
            throw std::invalid_argument("the solution does not fit the scene: element " + std::to_string(e) +
                                        " is not on face " + std::to_string(patch.face) + " of surface " +
                                        std::to_string(patch.surface) + " (the scene has " +
                                        std::to_string(scene.surfaces.size()) + " surfaces)");
        }
    }
}

}  // namespace rad
