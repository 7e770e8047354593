#include "rad/ray/ray_scene.hpp"

#include <embree3/rtcore.h>

#include <glm/common.hpp>
#include <limits>
#include <vector>

#include <algorithm>
#include <array>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

namespace rad {

namespace {

const char* error_name(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "no error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "unsupported CPU";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
        default:
            return "unknown error";
    }
}

// Embree's (unnormalized) geometric normal Ng of a quad points to the side from which its corners run
// counter-clockwise, our front, so a ray reaches a front when it runs against Ng. tests/transport/test_form_factors_embree_scene.cpp pins
// this down.
bool reaches_front(const RTCRayHit& hit) {
    return hit.ray.dir_x * hit.hit.Ng_x + hit.ray.dir_y * hit.hit.Ng_y + hit.ray.dir_z * hit.hit.Ng_z < 0.0f;
}

// Rays go to Embree in groups of this many through its stream interface: on the Cornell box's hemisphere
// rays, rtcOccluded1M ran at about 1.7x the rate of one rtcOccluded1 call per ray, and rtcIntersect1M as
// fast as rtcIntersect1 (bench_form_factors.cpp). The coherent-ray flag made both 2-3x slower on them.
constexpr std::size_t kStreamSize = 64;

// The ray in the normalized frame: o' = (o − centre) / scale and d' = d / scale keep every parameter t.
void to_embree(const Ray& in, const glm::dvec3& centre, double inverse_scale, RTCRay& out) {
    const glm::vec3 origin((in.origin - centre) * inverse_scale);
    const glm::vec3 direction(in.direction * inverse_scale);
    out.org_x = origin.x;
    out.org_y = origin.y;
    out.org_z = origin.z;
    out.tnear = in.tnear;
    out.dir_x = direction.x;
    out.dir_y = direction.y;
    out.dir_z = direction.z;
    out.time = 0.0f;
    out.tfar = in.tfar;
    out.mask = 0xffffffffu;
    out.id = 0;
    out.flags = 0;
}

}  // namespace

struct RayScene::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    // The corners in the normalized frame; one spare element, as Embree reads the last with a 16-byte load.
    std::vector<glm::vec3> vertices;
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::string message;

    // Embree calls this from whichever thread hit the error; C code cannot carry an exception, so the first
    // message is kept and thrown by throw_if_failed() on our side of the call.
    static void on_error(void* self, RTCError code, const char* text) {
        auto& embree = *static_cast<Embree*>(self);
        std::lock_guard lock(embree.mutex);
        if (embree.failed) return;
        embree.message = std::string("Embree: ") + error_name(code) + (text ? std::string(": ") + text : "");
        embree.failed = true;
    }

    void throw_if_failed() {
        if (!failed) return;
        std::lock_guard lock(mutex);
        throw std::runtime_error(message);
    }

    ~Embree() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

RayScene::RayScene(const PatchMesh& patches, const char* device_config)
    : embree_(std::make_unique<Embree>()) {
    Embree& e = *embree_;
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : patches.points) low = glm::min(low, p), high = glm::max(high, p);
    if (!patches.points.empty()) {
        centre_ = 0.5 * (low + high);
        const double extent = std::max({high.x - low.x, high.y - low.y, high.z - low.z});
        if (extent > 0.0) inverse_scale_ = 1.0 / extent;
    }
    e.vertices.reserve(patches.points.size() + 1);
    for (const glm::dvec3& p : patches.points) e.vertices.emplace_back((p - centre_) * inverse_scale_);
    e.device = rtcNewDevice(device_config);
    if (!e.device) {
        throw std::runtime_error(std::string("Embree: cannot create a device: ") +
                                 error_name(rtcGetDeviceError(nullptr)));
    }
    rtcSetDeviceErrorFunction(e.device, &Embree::on_error, &e);
    e.scene = rtcNewScene(e.device);
    e.throw_if_failed();
    rtcSetSceneBuildQuality(e.scene, RTC_BUILD_QUALITY_HIGH);
    // Watertight: without it one ray in millions slips between two patches along their shared edge and
    // leaves a closed room (tests/hard/test_hard_meeting_surfaces.cpp, Seams).
    rtcSetSceneFlags(e.scene, RTC_SCENE_FLAG_ROBUST);

    RTCGeometry quads = rtcNewGeometry(e.device, RTC_GEOMETRY_TYPE_QUAD);
    e.throw_if_failed();
    rtcSetSharedGeometryBuffer(quads, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, e.vertices.data(), 0,
                               sizeof(glm::vec3), e.vertices.size());
    rtcSetSharedGeometryBuffer(quads, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, patches.corners.data(), 0,
                               sizeof(glm::uvec4), patches.corners.size());
    rtcCommitGeometry(quads);
    rtcAttachGeometry(e.scene, quads);  // geometry ID 0: primID is the patch index
    rtcReleaseGeometry(quads);
    rtcCommitScene(e.scene);
    e.throw_if_failed();
}

RayScene::~RayScene() = default;

void RayScene::occluded(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
    if (blocked.size() < rays.size())
        throw std::invalid_argument("RayScene::occluded: result span too small");
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::array<RTCRay, kStreamSize> stream;
    for (std::size_t first = 0; first < rays.size(); first += kStreamSize) {
        const std::size_t count = std::min(kStreamSize, rays.size() - first);
        for (std::size_t k = 0; k < count; ++k)
            to_embree(rays[first + k], centre_, inverse_scale_, stream[k]);
        rtcOccluded1M(embree_->scene, &context, stream.data(), static_cast<unsigned>(count), sizeof(RTCRay));
        // Embree marks an occluded ray by setting its tfar to -inf.
        for (std::size_t k = 0; k < count; ++k) blocked[first + k] = stream[k].tfar < 0.0f ? 1 : 0;
    }
    embree_->throw_if_failed();
}

void RayScene::intersect(std::span<const Ray> rays, std::span<RayHit> hits) const {
    if (hits.size() < rays.size()) throw std::invalid_argument("RayScene::intersect: result span too small");
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    std::array<RTCRayHit, kStreamSize> stream;
    for (std::size_t first = 0; first < rays.size(); first += kStreamSize) {
        const std::size_t count = std::min(kStreamSize, rays.size() - first);
        for (std::size_t k = 0; k < count; ++k) {
            to_embree(rays[first + k], centre_, inverse_scale_, stream[k].ray);
            stream[k].hit.geomID = RTC_INVALID_GEOMETRY_ID;
            stream[k].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect1M(embree_->scene, &context, stream.data(), static_cast<unsigned>(count),
                       sizeof(RTCRayHit));
        for (std::size_t k = 0; k < count; ++k) {
            const RTCRayHit& h = stream[k];
            RayHit& out = hits[first + k];
            out.t = h.ray.tfar;
            if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
                out.patch = RayHit::kMissed;
            } else {
                out.patch = reaches_front(h) ? h.hit.primID : RayHit::kBackFace;
            }
        }
    }
    embree_->throw_if_failed();
}

}  // namespace rad
