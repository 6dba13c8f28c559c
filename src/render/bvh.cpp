#include "render/bvh.h"

#include "render/embree_util.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <fmt/format.h>

namespace veduta {

namespace {

struct MemoryCounter {
    std::atomic<int64_t> current{0};
    std::atomic<int64_t> peak{0};
};

bool countMemory(void *user, ssize_t bytes, bool /*post*/) {
    auto *counter = static_cast<MemoryCounter *>(user);
    int64_t now = counter->current.fetch_add(bytes) + bytes;
    int64_t peak = counter->peak.load();
    while (now > peak && !counter->peak.compare_exchange_weak(peak, now)) {}
    return true;
}

// The first error Embree reports. Embree calls in from its own threads, through C frames:
// record under a lock, never throw.
struct ErrorRecord {
    std::mutex mutex;
    std::string message;
};

void recordError(void *user, RTCError code, const char *message) {
    auto *record = static_cast<ErrorRecord *>(user);
    std::lock_guard lock(record->mutex);
    if (record->message.empty())
        record->message = fmt::format("Embree error {}: {}", int(code), message ? message : "");
}

void *newBuffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, size_t stride, size_t count) {
    void *buffer = rtcSetNewGeometryBuffer(geometry, type, 0, format, stride, count);
    if (!buffer) throw std::runtime_error("Embree could not allocate a geometry buffer (out of memory?)");
    return buffer;
}

// What the occlusion filter of a geometry with surfaces that pass light needs to know.
struct FilterGeometry {
    const Mesh *mesh = nullptr;
    const std::vector<uint8_t> *passesLight = nullptr;   // by material
    const std::vector<MaterialId> *overrides = nullptr;  // by instance; null for a baked mesh
    uint32_t meshCount = 0;                              // instance geometry ids start here
};

// Embree hands the filter the query's context; ours follows Embree's in one struct.
struct ShadowContext {
    RTCIntersectContext embree;
    PassedSurfaces *passed = nullptr;  // null: every surface stops the ray
};

bool sameSurface(const Hit &a, const Hit &b) {
    return a.instanced == b.instanced && a.index == b.index && a.primitive == b.primitive;
}

// The occlusion filter: a surface whose material passes light is noted and the ray goes on;
// any other hit stands, and ends the query. Embree may report a triangle twice (it can sit in
// two leaves); it is noted once.
void passLight(const RTCFilterFunctionNArguments *args) {
    if (args->N != 1 || args->valid[0] == 0) return;
    const auto *context = reinterpret_cast<const ShadowContext *>(args->context);
    if (!context->passed) return;
    const auto *geometry = static_cast<const FilterGeometry *>(args->geometryUserPtr);
    uint32_t primitive = RTCHitN_primID(args->hit, 1, 0);
    uint32_t instance = RTCHitN_instID(args->hit, 1, 0, 0);
    MaterialId material = geometry->mesh->triangleMaterials[primitive];
    Hit hit;
    hit.instanced = instance != RTC_INVALID_GEOMETRY_ID;
    if (hit.instanced) {
        hit.index = instance - geometry->meshCount;
        MaterialId override = (*geometry->overrides)[hit.index];
        if (override != kNoMaterial) material = override;
    } else {
        hit.index = RTCHitN_geomID(args->hit, 1, 0);
    }
    if (!(*geometry->passesLight)[material]) return;
    hit.t = RTCRayN_tfar(args->ray, 1, 0);
    hit.primitive = primitive;
    hit.u = RTCHitN_u(args->hit, 1, 0);
    hit.v = RTCHitN_v(args->hit, 1, 0);
    PassedSurfaces &passed = *context->passed;
    for (uint32_t i = 0; i < passed.count; ++i)
        if (sameSurface(passed.hits[i], hit)) {
            args->valid[0] = 0;
            return;
        }
    if (passed.count == PassedSurfaces::kCapacity) {
        passed.overflow = true;  // the hit stands: the caller traces the ray again, surface by surface
        return;
    }
    passed.hits[passed.count++] = hit;
    args->valid[0] = 0;
}

// The mesh's own arrays are handed to Embree, not copied (a 13.6-million-triangle terrain
// would otherwise hold 250 MB twice): the RenderScene outlives the Bvh (bvh.h). Embree reads
// vertices with 16-byte loads, so a float3 buffer needs 4 readable bytes after its last
// vertex; spare capacity in `positions` gives them, else the vertices are copied. A mesh with
// surfaces that pass light gets the occlusion filter.
RTCGeometry makeTriangles(RTCDevice device, const Mesh &mesh, const FilterGeometry *filter) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    static_assert(sizeof(Vec3f) == 3 * sizeof(float));
    if (mesh.positions.capacity() > mesh.positions.size()) {
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh.positions.data(), 0,
                                   sizeof(Vec3f), mesh.vertexCount());
    } else {
        auto *vertices = static_cast<float *>(
            newBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertexCount()));
        for (size_t i = 0; i < mesh.vertexCount(); ++i) {
            vertices[3 * i] = mesh.positions[i].x;
            vertices[3 * i + 1] = mesh.positions[i].y;
            vertices[3 * i + 2] = mesh.positions[i].z;
        }
    }
    if (mesh.indices.empty()) {
        newBuffer(geometry, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), 0);
    } else {
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                                   3 * sizeof(uint32_t), mesh.triangleCount());
    }
    if (filter) {
        rtcSetGeometryUserData(geometry, const_cast<FilterGeometry *>(filter));
        rtcSetGeometryOccludedFilterFunction(geometry, passLight);
    }
    rtcCommitGeometry(geometry);
    return geometry;
}

bool anyPasses(const Mesh &mesh, const std::vector<uint8_t> &passesLight) {
    return std::any_of(mesh.triangleMaterials.begin(), mesh.triangleMaterials.end(),
                       [&](MaterialId m) { return passesLight[m] != 0; });
}

}  // namespace

struct Bvh::Impl {
    MemoryCounter memory;
    ErrorRecord error;
    RTCDevice device = nullptr;
    std::vector<RTCScene> prototypes;
    RTCScene top = nullptr;
    uint32_t meshCount = 0;
    std::vector<uint8_t> passesLight;    // by material
    std::vector<MaterialId> overrides;   // by instance
    std::deque<FilterGeometry> filters;  // the geometries' filter data, at fixed addresses

    ~Impl() {
        if (top) rtcReleaseScene(top);
        for (RTCScene s : prototypes) rtcReleaseScene(s);
        if (device) rtcReleaseDevice(device);
    }
};

Bvh::Bvh(const RenderScene &scene) : impl_(std::make_unique<Impl>()) {
    auto start = std::chrono::steady_clock::now();
    impl_->device = rtcNewDevice("verbose=0");
    if (!impl_->device) throw std::runtime_error("cannot create an Embree device");
    rtcSetDeviceErrorFunction(impl_->device, recordError, &impl_->error);
    rtcSetDeviceMemoryMonitorFunction(impl_->device, countMemory, &impl_->memory);

    for (const Material &m : scene.materials) impl_->passesLight.push_back(m.passesLight());
    impl_->meshCount = uint32_t(scene.meshes.size());
    // A prototype needs the filter when a triangle of it passes light, or an instance makes it.
    std::vector<uint8_t> prototypePasses(scene.prototypes.size(), 0);
    for (const Instance &instance : scene.instances) {
        impl_->overrides.push_back(instance.materialOverride);
        if (instance.materialOverride != kNoMaterial && impl_->passesLight[instance.materialOverride])
            prototypePasses[instance.prototype] = 1;
    }
    auto filterFor = [&](const Mesh &mesh, bool instanced, bool passes) -> const FilterGeometry * {
        if (!passes && !anyPasses(mesh, impl_->passesLight)) return nullptr;
        return &impl_->filters.emplace_back(
            FilterGeometry{&mesh, &impl_->passesLight, instanced ? &impl_->overrides : nullptr, impl_->meshCount});
    };

    for (size_t p = 0; p < scene.prototypes.size(); ++p) {
        const Mesh &prototype = scene.prototypes[p];
        RTCScene s = rtcNewScene(impl_->device);
        RTCGeometry g = makeTriangles(impl_->device, prototype, filterFor(prototype, true, prototypePasses[p]));
        rtcAttachGeometryByID(s, g, 0);
        rtcReleaseGeometry(g);
        rtcCommitScene(s);
        impl_->prototypes.push_back(s);
    }

    // Geometry ids: baked meshes first, then instances, so a hit's id says which it is.
    impl_->top = rtcNewScene(impl_->device);
    for (uint32_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh &mesh = scene.meshes[i].mesh;
        RTCGeometry g = makeTriangles(impl_->device, mesh, filterFor(mesh, false, false));
        rtcAttachGeometryByID(impl_->top, g, i);
        rtcReleaseGeometry(g);
    }
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance &instance = scene.instances[i];
        RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, impl_->prototypes[instance.prototype]);
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, instance.objectToWorld.m.data());
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(impl_->top, g, impl_->meshCount + i);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(impl_->top);
    if (!impl_->error.message.empty()) throw std::runtime_error(impl_->error.message);

    stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_.bytes = impl_->memory.current.load();
    stats_.peakBytes = impl_->memory.peak.load();
}

Bvh::~Bvh() = default;

void *Bvh::embreeScene() const { return impl_->top; }

std::optional<Hit> Bvh::intersect(const Ray &ray, bool coherent) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    RTCRayHit rh = toRayHit(ray, std::numeric_limits<float>::infinity());
    rtcIntersect1(impl_->top, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    Hit hit;
    hit.t = rh.ray.tfar;
    hit.instanced = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
    hit.index = hit.instanced ? rh.hit.instID[0] - impl_->meshCount : rh.hit.geomID;
    hit.primitive = rh.hit.primID;
    hit.u = rh.hit.u;
    hit.v = rh.hit.v;
    return hit;
}

bool Bvh::occluded(const Ray &ray, float tMax) const {
    ShadowContext context;
    rtcInitIntersectContext(&context.embree);
    context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    RTCRay r = toRayHit(ray, tMax).ray;
    rtcOccluded1(impl_->top, &context.embree, &r);
    return r.tfar < 0;  // Embree sets tfar to -inf on a hit
}

bool Bvh::occluded(const Ray &ray, float tMax, PassedSurfaces &passed) const {
    passed.count = 0;
    passed.overflow = false;
    ShadowContext context;
    rtcInitIntersectContext(&context.embree);
    context.embree.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    context.passed = &passed;
    RTCRay r = toRayHit(ray, tMax).ray;
    rtcOccluded1(impl_->top, &context.embree, &r);
    if (r.tfar < 0) return true;
    // Embree meets them in the order of its tree; the caller weighs them nearest first, so the
    // product is the same however the tree was built.
    auto nearer = [](const Hit &a, const Hit &b) {
        if (a.t != b.t) return a.t < b.t;
        if (a.instanced != b.instanced) return a.instanced < b.instanced;
        return a.index != b.index ? a.index < b.index : a.primitive < b.primitive;
    };
    std::sort(passed.hits.begin(), passed.hits.begin() + passed.count, nearer);
    return false;
}

}  // namespace veduta
