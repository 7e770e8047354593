#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <span>

#include "rad/patches.hpp"

namespace rad {

// A ray segment: points origin + t * direction for t in [tnear, tfar]. The direction need not be unit.
struct Ray {
    glm::vec3 origin{0.0f};
    float tnear = 0.0f;
    glm::vec3 direction{0.0f, 0.0f, 1.0f};
    float tfar = 1e30f;
};

// What a closest-hit query found: the patch whose front the ray reaches first, or one of the two markers.
struct RayHit {
    static constexpr std::uint32_t kMissed = 0xffffffffu;    // left the scene
    static constexpr std::uint32_t kBackFace = 0xfffffffeu;  // reached a back face first: blocked
    std::uint32_t patch = kMissed;
    float t = 0.0f;
};

// The patches as an Embree BVH, for batched ray queries from any number of threads at once. This class is
// the only code that sees Embree: its vertex and index buffers are the PatchMesh's own (shared, not
// copied), so the PatchMesh must outlive it and stay unchanged. Embree's errors become std::runtime_error.
class RayScene {
  public:
    // `device_config` is Embree's device configuration string (empty: Embree's defaults).
    explicit RayScene(const PatchMesh& patches, const char* device_config = "");
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // blocked[k] = 1 when anything, front or back, lies on rays[k] between tnear and tfar; else 0.
    void occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const;

    // hits[k] = the first surface rays[k] meets: a patch seen from its front, kBackFace or kMissed.
    void intersect(std::span<const Ray> rays, std::span<RayHit> hits) const;

  private:
    struct Embree;
    std::unique_ptr<Embree> embree_;
};

}  // namespace rad
