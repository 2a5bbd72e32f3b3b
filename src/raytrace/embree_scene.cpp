#include <raytrace/embree_scene.h>

#include <core/check.h>

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <string>

namespace rayrad::raytrace {

namespace {

// Embree reports errors through a C callback; throwing through C frames is undefined,
// so remember the first message and turn it into an InternalError after the call.
void onEmbreeError(void* user, RTCError code, const char* message) {
    auto* first = static_cast<std::string*>(user);
    if (first->empty())
        *first = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

}  // namespace

struct EmbreeScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string error;
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

EmbreeScene::EmbreeScene(const radiosity::PatchMesh& mesh, double epsilon)
    : m_impl(std::make_unique<Impl>()), m_epsilon(epsilon) {
    m_impl->device = rtcNewDevice(nullptr);
    if (!m_impl->device) throw InternalError("cannot create an Embree device");
    rtcSetDeviceErrorFunction(m_impl->device, onEmbreeError, &m_impl->error);
    m_impl->scene = rtcNewScene(m_impl->device);
    rtcSetSceneBuildQuality(m_impl->scene, RTC_BUILD_QUALITY_HIGH);

    RTCGeometry geom = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // rtcSetNewGeometryBuffer allocates with the padding Embree's 16-byte loads need.
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                           3 * sizeof(float), mesh.vertices.size()));
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        vb[3 * i + 0] = static_cast<float>(mesh.vertices[i].x);
        vb[3 * i + 1] = static_cast<float>(mesh.vertices[i].y);
        vb[3 * i + 2] = static_cast<float>(mesh.vertices[i].z);
    }
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                              3 * sizeof(unsigned), mesh.patches.size()));
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (int k = 0; k < 3; ++k) ib[3 * i + k] = mesh.patches[i].v[k];
    rtcCommitGeometry(geom);
    rtcAttachGeometry(m_impl->scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(m_impl->scene);
    if (!m_impl->error.empty()) throw InternalError(m_impl->error);
}

EmbreeScene::~EmbreeScene() = default;

bool EmbreeScene::visible(const Vec3& from, const Vec3& to) const {
    Vec3 d = to - from;
    double len = glm::length(d);
    if (len <= 2 * m_epsilon) return true;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = static_cast<float>(from.x);
    ray.org_y = static_cast<float>(from.y);
    ray.org_z = static_cast<float>(from.z);
    ray.dir_x = static_cast<float>(d.x / len);
    ray.dir_y = static_cast<float>(d.y / len);
    ray.dir_z = static_cast<float>(d.z / len);
    ray.tnear = static_cast<float>(m_epsilon);
    ray.tfar = static_cast<float>(len - m_epsilon);
    ray.mask = 0xFFFFFFFFu;  // Debian's Embree has ray masks on: mask 0 would miss everything
    ray.flags = 0;
    rtcOccluded1(m_impl->scene, &context, &ray);
    return ray.tfar >= 0;  // an occluder sets tfar to -inf
}

Hit EmbreeScene::intersect(const Vec3& origin, const Vec3& dir, double tnear, double tfar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(origin.x);
    rh.ray.org_y = static_cast<float>(origin.y);
    rh.ray.org_z = static_cast<float>(origin.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    rh.ray.tnear = static_cast<float>(tnear);
    rh.ray.tfar = std::isfinite(tfar) ? static_cast<float>(tfar) : std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_impl->scene, &context, &rh);
    Hit h;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    h.found = true;
    h.patch = rh.hit.primID;
    h.u = rh.hit.u;
    h.v = rh.hit.v;
    h.t = rh.ray.tfar;
    return h;
}

}  // namespace rayrad::raytrace
