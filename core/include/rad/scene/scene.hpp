#pragma once

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rad/scene/material.hpp"
#include "rad/scene/sky.hpp"

namespace rad {

struct SurfaceMeshTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};

// A surface's geometry: planar convex polygons, counter-clockwise seen from the lit (front) side.
using SurfaceMesh = OpenMesh::PolyMesh_ArrayKernelT<SurfaceMeshTraits>;

// A named piece of the scene with one material. A back-to-back surface is one side of a two-sided surface:
// another surface covers each of its faces with the opposite winding (the other side), so a ray that reaches
// its back goes on to that side's front instead of being blocked.
struct Surface {
    std::string name;
    Material material;
    SurfaceMesh mesh;
    bool back_to_back = false;
};

// A pinhole camera; fov is the vertical field of view in degrees.
struct Camera {
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0.0, 0.0, -1.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fov_degrees = 45.0;
};

struct BoundingBox {
    glm::dvec3 min{std::numeric_limits<double>::infinity()};
    glm::dvec3 max{-std::numeric_limits<double>::infinity()};

    void extend(const glm::dvec3& p);
    bool empty() const { return min.x > max.x; }
    glm::dvec3 extent() const { return empty() ? glm::dvec3(0.0) : max - min; }
    double largest_extent() const;
};

struct Scene {
    std::string source;  // file path or builtin:NAME, for messages
    std::vector<Surface> surfaces;
    std::optional<Camera> camera;
    Sky sky;  // none unless the command line or the file asks for one
    Sun sun;
    std::vector<std::string> warnings;  // for the caller to show; the library prints nothing
};

inline glm::dvec3 to_glm(const OpenMesh::Vec3d& p) {
    return {p[0], p[1], p[2]};
}

double face_area(const SurfaceMesh& mesh, SurfaceMesh::FaceHandle face);
double surface_area(const SurfaceMesh& mesh);
double total_area(const Scene& scene);
BoundingBox bounding_box(const Scene& scene);
bool has_emitter(const Scene& scene);
// Whether a sky or a sun lights the scene from outside.
bool has_outside_light(const Scene& scene);
// The warning a loader gives for a scene whose materials emit nothing, which a sky or sun makes moot.
std::string no_emitter_warning(const std::string& source);
// The indices of the surfaces whose material emits.
std::vector<std::uint32_t> emitting_surfaces(const Scene& scene);
// The luminance of the emitted radiance Le of each of `surfaces` (Rec. 709), in their order.
std::vector<double> emitted_luminance(const Scene& scene, std::span<const std::uint32_t> surfaces);

}  // namespace rad
