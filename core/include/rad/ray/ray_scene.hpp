#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>

#include "rad/mesh/patch_mesh.hpp"

namespace rad {

// A ray segment: points origin + t * direction for t in [tnear, tfar]. The direction need not be unit.
// Origin and direction are in double, as callers compute them: RayScene rounds them to float only after
// moving them into the scene's own normalized frame, so a scene scaled by any factor traces the same rays.
struct Ray {
    glm::dvec3 origin{0.0};
    float tnear = 0.0f;
    glm::dvec3 direction{0.0, 0.0, 1.0};
    float tfar = 1e30f;
};

// What a closest-hit query found: the patch whose front the ray reaches first, or one of the two markers.
struct RayHit {
    static constexpr std::uint32_t kMissed = 0xffffffffu;    // left the scene
    static constexpr std::uint32_t kBackFace = 0xfffffffeu;  // reached a back face first: blocked
    std::uint32_t patch = kMissed;
    float t = 0.0f;
    std::uint32_t met = kMissed;  // the patch met, from its front or its back; kMissed when none
};

// The patches as an Embree BVH, for batched ray queries from any number of threads at once. This class is
// the only code that sees Embree. Embree works in float; its vertices are the patches' corners moved to the
// bounding box's centre and divided by its largest extent, rounded to float from double, and rays are moved
// the same way. So the float geometry, and every hit, does not depend on where the scene sits or how large
// it is (a scene at 1e-3 or 1e4 times its size gives the same form factors). The index buffer is the
// PatchMesh's own (shared), so the PatchMesh must outlive it and stay unchanged. Embree's errors become
// std::runtime_error.
class RayScene {
  public:
    // `device_config` is Embree's device configuration string (empty: Embree's defaults).
    explicit RayScene(const PatchMesh& patches, const char* device_config = "");
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // blocked[k] = 1 when anything, front or back, lies on rays[k] between tnear and tfar; else 0.
    void occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;

    // hits[k] = the first surface rays[k] meets: a patch seen from its front, kBackFace or kMissed (and in
    // `met` the patch, whichever side). The back of a back-to-back patch (PatchMesh::is_back_to_back) is
    // passed through: the other side's front is there.
    void intersect(std::span<const Ray> rays, std::span<RayHit> hits) const;

  private:
    struct Embree;
    std::unique_ptr<Embree> embree_;
    glm::dvec3 centre_{0.0};
    double inverse_scale_ = 1.0;
};

}  // namespace rad
