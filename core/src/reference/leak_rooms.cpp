#include "rad/reference/leak_rooms.hpp"

#include <algorithm>
#include <numbers>

#include "util/luminance.hpp"

namespace rad {

namespace {

BoundingBox box(const glm::dvec3& lower, const glm::dvec3& upper) {
    BoundingBox b;
    b.extend(lower);
    b.extend(upper);
    return b;
}

}  // namespace

std::span<const LeakRoom> leak_rooms() {
    static const BoundingBox unit = box(glm::dvec3(0.0), glm::dvec3(1.0));
    static const LeakRoom rooms[] = {
        {"leak_inward_box", "one box of six inward faces", true, unit},
        {"leak_slabs_touching", "six wall slabs touching face to face", true, unit},
        {"leak_slabs_overlap", "six slabs running through each other at the corners", true, unit},
        {"leak_slabs_edges", "six slabs meeting only along the interior's edges", true, unit},
        {"leak_floor_under", "wall slabs on a floor that runs on under them", true, unit},
        {"leak_two_rooms", "a dark room beside one lit by a lamp, one slab between", false,
         box(glm::dvec3(1.1, 0.0, 0.0), glm::dvec3(2.1, 1.0, 1.0))},
        {"leak_leg_through", "a table's legs through the floor slab, a beam through a wall", true, unit},
    };
    return rooms;
}

bool looks_into(const Patch& patch, const BoundingBox& interior) {
    const glm::dvec3 probe = patch.centroid + 1e-3 * patch.normal;
    for (int a = 0; a < 3; ++a) {
        if (patch.centroid[a] < interior.min[a] - 1e-9 || patch.centroid[a] > interior.max[a] + 1e-9)
            return false;
        if (probe[a] <= interior.min[a] || probe[a] >= interior.max[a]) return false;
    }
    return true;
}

Leak measure_leak(const Scene& scene, const PatchMesh& elements, std::span<const glm::dvec3> radiosity,
                  const BoundingBox& interior) {
    Leak leak;
    double power = 0.0, area = 0.0;
    for (std::size_t i = 0; i < radiosity.size(); ++i) {
        const Patch& p = elements.patches[i];
        const glm::dvec3& b = radiosity[i];
        if (looks_into(p, interior)) {
            ++leak.inside;
            leak.worst_inside = std::max({leak.worst_inside, b.x, b.y, b.z});
        } else if (luminance(b) > 0.0 && !scene.surfaces[p.surface].material.emits()) {
            power += p.area * luminance(b);
            area += p.area;
        }
    }
    leak.lit_mean = area > 0.0 ? power / area : 0.0;
    return leak;
}

Camera interior_camera(const BoundingBox& interior) {
    Camera camera;
    camera.eye = 0.5 * (interior.min + interior.max);
    camera.target = interior.min;
    camera.up = glm::dvec3(0.0, 1.0, 0.0);
    camera.fov_degrees = 100.0;
    return camera;
}

double image_leak(const Image& radiance, double lit_mean) {
    double brightest = 0.0;
    for (const glm::vec3& p : radiance.pixels)
        brightest = std::max({brightest, double(p.x), double(p.y), double(p.z)});
    return lit_mean > 0.0 ? std::numbers::pi * brightest / lit_mean : 0.0;
}

}  // namespace rad
