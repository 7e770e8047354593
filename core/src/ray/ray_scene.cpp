#include "rad/ray/ray_scene.hpp"

#include <embree3/rtcore.h>
// The builder header needs rtcore.h first.
#include <embree3/rtcore_builder.h>

#include <glm/common.hpp>
#include <limits>
#include <new>
#include <vector>

#include <algorithm>
#include <array>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

#include "rad/ray/box_tree.hpp"

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
// counter-clockwise, our front, so a ray reaches a front when it runs against Ng.
// tests/transport/test_form_factors_embree_scene.cpp pins this down.
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
    // Per patch, its surface.
    std::vector<std::uint32_t> surface;
    // Per patch, 1 where a ray reaching its back goes on (PatchMesh::is_back_to_back); empty: none does.
    std::vector<std::uint8_t> see_through_back;
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::string message;

    // A filter's hit i: the ray's direction against the geometric normal (negative: it meets a front).
    static float facing(const RTCFilterFunctionNArguments* args, unsigned i) {
        return RTCRayN_dir_x(args->ray, args->N, i) * RTCHitN_Ng_x(args->hit, args->N, i) +
               RTCRayN_dir_y(args->ray, args->N, i) * RTCHitN_Ng_y(args->hit, args->N, i) +
               RTCRayN_dir_z(args->ray, args->N, i) * RTCHitN_Ng_z(args->hit, args->N, i);
    }

    // Closest-hit queries skip the back of a back-to-back patch: the other side of its two-sided surface
    // lies in the same plane, and the ray meets that side's front there. Occlusion queries keep every hit,
    // as a two-sided surface blocks light from both sides.
    static void skip_back_to_back(const RTCFilterFunctionNArguments* args) {
        const auto& embree = *static_cast<const Embree*>(args->geometryUserPtr);
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] != -1) continue;
            const unsigned patch = RTCHitN_primID(args->hit, args->N, i);
            if (embree.see_through_back[patch] == 0) continue;
            if (facing(args, i) >= 0.0f) args->valid[i] = 0;
        }
    }

    // The second look at a ray that met a back: only the fronts of the back's surface count.
    struct FrontsOfSurface {
        RTCIntersectContext context;  // first, so Embree's pointer to it is one to this
        std::uint32_t surface = 0;
    };
    static void keep_fronts_of_surface(const RTCFilterFunctionNArguments* args) {
        const auto& embree = *static_cast<const Embree*>(args->geometryUserPtr);
        const auto& wanted = *reinterpret_cast<const FrontsOfSurface*>(args->context);
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] != -1) continue;
            const unsigned patch = RTCHitN_primID(args->hit, args->N, i);
            if (facing(args, i) >= 0.0f || embree.surface[patch] != wanted.surface) args->valid[i] = 0;
        }
    }

    // A ray that crosses the edge between a front and a back of one surface (a ball's outline, met at a
    // grazing angle) meets both at one distance, and Embree may keep the back: the ray touched the
    // surface's outside, and reaches the front. One ray in tens of millions on the furnace of a million
    // triangles; taken as backs, they left single leaves 2 % dark.
    void fronts_at_the_same_distance(RTCRayHit& found) const {
        FrontsOfSurface wanted;
        rtcInitIntersectContext(&wanted.context);
        wanted.context.filter = &keep_fronts_of_surface;
        wanted.surface = surface[found.hit.primID];
        RTCRayHit again = found;
        // Only the fronts within a few float steps of the back: a short segment, soon traversed.
        again.ray.tnear = std::max(found.ray.tnear, found.ray.tfar * (1.0f - 1e-5f) - 1e-7f);
        again.ray.tfar = found.ray.tfar * (1.0f + 1e-5f) + 1e-7f;
        again.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &wanted.context, &again);
        if (again.hit.geomID != RTC_INVALID_GEOMETRY_ID) found = again;
    }

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
    e.surface.reserve(patches.size());
    for (const Patch& p : patches.patches) e.surface.push_back(p.surface);
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
    // The context filter: only the second look at a ray that met a back (fronts_at_the_same_distance).
    rtcSetSceneFlags(e.scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);

    RTCGeometry quads = rtcNewGeometry(e.device, RTC_GEOMETRY_TYPE_QUAD);
    e.throw_if_failed();
    rtcSetSharedGeometryBuffer(quads, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, e.vertices.data(), 0,
                               sizeof(glm::vec3), e.vertices.size());
    rtcSetSharedGeometryBuffer(quads, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, patches.corners.data(), 0,
                               sizeof(glm::uvec4), patches.corners.size());
    rtcSetGeometryUserData(quads, &e);
    if (!patches.back_to_back.empty()) {
        e.see_through_back.resize(patches.size());
        for (std::size_t p = 0; p < patches.size(); ++p) e.see_through_back[p] = patches.is_back_to_back(p);
        rtcSetGeometryIntersectFilterFunction(quads, &Embree::skip_back_to_back);
    }
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
                out.met = RayHit::kMissed;
                continue;
            }
            if (!reaches_front(h)) embree_->fronts_at_the_same_distance(stream[k]);
            out.t = h.ray.tfar;
            out.met = h.hit.primID;
            out.patch = reaches_front(h) ? h.hit.primID : RayHit::kBackFace;
        }
    }
    embree_->throw_if_failed();
}

// The builder's nodes, in memory Embree's thread-local allocator owns until the BVH is released.
namespace {

struct BuildNode {
    bool leaf = false;
    unsigned count = 0;
    BuildNode* children[2] = {nullptr, nullptr};
    RTCBounds bounds[2] = {};
    std::uint32_t* items = nullptr;  // leaf: the primitive ids
};

void* create_node(RTCThreadLocalAllocator allocator, unsigned int child_count, void*) {
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(BuildNode), 16);
    auto* node = new (memory) BuildNode;
    node->count = child_count;
    return node;
}

void set_children(void* node, void** children, unsigned int count, void*) {
    for (unsigned i = 0; i < count; ++i)
        static_cast<BuildNode*>(node)->children[i] = static_cast<BuildNode*>(children[i]);
}

void set_bounds(void* node, const RTCBounds** bounds, unsigned int count, void*) {
    for (unsigned i = 0; i < count; ++i) static_cast<BuildNode*>(node)->bounds[i] = *bounds[i];
}

void* create_leaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* primitives, size_t count,
                  void*) {
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(BuildNode), 16);
    auto* node = new (memory) BuildNode;
    node->leaf = true;
    node->count = static_cast<unsigned>(count);
    node->items =
        static_cast<std::uint32_t*>(rtcThreadLocalAlloc(allocator, count * sizeof(std::uint32_t), 4));
    for (size_t i = 0; i < count; ++i) node->items[i] = primitives[i].primID;
    // Embree hands a leaf's primitives in an order that may depend on the threads.
    std::sort(node->items, node->items + count);
    return node;
}

Box box_of(const RTCBounds& b) {
    return {glm::dvec3(b.lower_x, b.lower_y, b.lower_z), glm::dvec3(b.upper_x, b.upper_y, b.upper_z)};
}

// Depth first from the root into `tree`; `index` was reserved for the node by its parent.
void flatten(const BuildNode& node, std::uint32_t index, BoxTree& tree) {
    tree.nodes[index].item_begin = static_cast<std::uint32_t>(tree.items.size());
    if (node.leaf) {
        tree.nodes[index].leaf = true;
        tree.nodes[index].first = static_cast<std::uint32_t>(tree.items.size());
        tree.nodes[index].count = node.count;
        tree.items.insert(tree.items.end(), node.items, node.items + node.count);
    } else {
        const auto first = static_cast<std::uint32_t>(tree.nodes.size());
        tree.nodes[index].leaf = false;
        tree.nodes[index].first = first;
        tree.nodes[index].count = node.count;
        tree.nodes.resize(tree.nodes.size() + node.count);
        for (unsigned c = 0; c < node.count; ++c) tree.nodes[first + c].bounds = box_of(node.bounds[c]);
        for (unsigned c = 0; c < node.count; ++c) flatten(*node.children[c], first + c, tree);
    }
    tree.nodes[index].item_end = static_cast<std::uint32_t>(tree.items.size());
}

}  // namespace

BoxTree build_box_tree(std::span<const Box> boxes, unsigned max_leaf_size) {
    BoxTree tree;
    tree.nodes.resize(1);
    if (boxes.empty()) return tree;
    Box all{boxes[0].lower, boxes[0].upper};
    std::vector<RTCBuildPrimitive> primitives(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        all.lower = glm::min(all.lower, boxes[i].lower);
        all.upper = glm::max(all.upper, boxes[i].upper);
        RTCBuildPrimitive& p = primitives[i];
        p.lower_x = static_cast<float>(boxes[i].lower.x);
        p.lower_y = static_cast<float>(boxes[i].lower.y);
        p.lower_z = static_cast<float>(boxes[i].lower.z);
        p.upper_x = static_cast<float>(boxes[i].upper.x);
        p.upper_y = static_cast<float>(boxes[i].upper.y);
        p.upper_z = static_cast<float>(boxes[i].upper.z);
        p.geomID = 0;
        p.primID = static_cast<unsigned>(i);
    }
    tree.nodes[0].bounds = all;
    RTCDevice device = rtcNewDevice("");
    if (!device) throw std::runtime_error("Embree: cannot create a device for the box tree");
    RTCBVH bvh = rtcNewBVH(device);
    RTCBuildArguments arguments = rtcDefaultBuildArguments();
    arguments.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
    arguments.maxBranchingFactor = 2;
    arguments.minLeafSize = 1;
    arguments.maxLeafSize = std::max(1u, max_leaf_size);
    arguments.bvh = bvh;
    arguments.primitives = primitives.data();
    arguments.primitiveCount = primitives.size();
    arguments.primitiveArrayCapacity = primitives.size();
    arguments.createNode = create_node;
    arguments.setNodeChildren = set_children;
    arguments.setNodeBounds = set_bounds;
    arguments.createLeaf = create_leaf;
    const auto* root = static_cast<const BuildNode*>(rtcBuildBVH(&arguments));
    if (!root) {
        rtcReleaseBVH(bvh);
        rtcReleaseDevice(device);
        throw std::runtime_error("Embree: the box tree could not be built");
    }
    tree.nodes.reserve(2 * boxes.size() / std::max(1u, max_leaf_size) + 2);
    tree.items.reserve(boxes.size());
    flatten(*root, 0, tree);
    rtcReleaseBVH(bvh);
    rtcReleaseDevice(device);
    return tree;
}

}  // namespace rad
