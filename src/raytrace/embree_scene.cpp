#include <raytrace/embree_scene.h>

#include <core/check.h>
#include <scene/polygon.h>

#include <embree3/rtcore.h>

#include <algorithm>
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

/// The context of every intersect() query: whether back faces of patches are passed.
struct QueryContext {
    RTCIntersectContext base;  ///< first member: Embree hands this pointer to the filter
    bool frontOnly = false;
};

/// Intersection filter on the patches: in a front-only query a ray passes back faces.
void frontFacesOnly(const RTCFilterFunctionNArguments* args);

}  // namespace

struct EmbreeScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string error;
    unsigned patchGeometry = RTC_INVALID_GEOMETRY_ID;
    unsigned mirrorGeometry = RTC_INVALID_GEOMETRY_ID;
    unsigned glassGeometry = RTC_INVALID_GEOMETRY_ID;
    std::vector<uint32_t> mirrorIndex, glassIndex;  ///< primitive → specular triangle
    /// Per patch, its front normal, for the front-only filter (a copy: the mesh may move
    /// with its owner while this scene lives on the heap; float: only its sign counts).
    std::vector<glm::vec3> normals;
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

namespace {
constexpr unsigned kOpaqueMask = 1u;  ///< patches and mirrors: block visibility
constexpr unsigned kGlassMask = 2u;   ///< glass: only primary and secondary rays see it
}  // namespace

namespace {
void frontFacesOnly(const RTCFilterFunctionNArguments* args) {
    if (!reinterpret_cast<const QueryContext*>(args->context)->frontOnly) return;
    const auto* impl = static_cast<const EmbreeScene::Impl*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const Vec3 dir(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                       RTCRayN_dir_z(args->ray, args->N, i));
        if (glm::dot(dir, Vec3(impl->normals[prim])) > 0) args->valid[i] = 0;  // a back face: look on
    }
}
}  // namespace

std::vector<SpecularTriangle> specularTriangles(const scene::Scene& scene) {
    std::vector<SpecularTriangle> out;
    for (const auto& g : scene.groups) {
        if (scene.isPatchSurface(g) || scene.materials[g.material].isOpening()) continue;  // openings let light through
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> v;
            for (uint32_t i : poly) v.push_back(g.positions[i]);
            Vec3 n = scene::polygonNormal(v);
            bool glass = scene.materials[g.material].kind == scene::SurfaceKind::Glass;
            for (const auto& t : scene::triangulate(v))
                out.push_back({{v[t[0]], v[t[1]], v[t[2]]}, n, g.material, glass});
        }
    }
    return out;
}

EmbreeScene::EmbreeScene(const radiosity::PatchMesh& mesh, double epsilon, const std::vector<SpecularTriangle>& specular)
    : m_impl(std::make_unique<Impl>()), m_epsilon(epsilon), m_specular(specular) {
    m_impl->device = rtcNewDevice(nullptr);
    if (!m_impl->device) throw InternalError("cannot create an Embree device");
    rtcSetDeviceErrorFunction(m_impl->device, onEmbreeError, &m_impl->error);
    m_impl->scene = rtcNewScene(m_impl->device);
    rtcSetSceneBuildQuality(m_impl->scene, RTC_BUILD_QUALITY_HIGH);
    // Watertight traversal: without it a ray through a shared edge of two triangles can
    // slip between them. On grid-meshed walls the rays between patch centroids cross
    // edges exactly, and light leaked through zero-thickness walls that way.
    rtcSetSceneFlags(m_impl->scene, RTC_SCENE_FLAG_ROBUST);

    // Geometry 0: the patches; then the specular triangles, split by mask.
    auto addTriangles = [&](const std::vector<Vec3>& vertices, const std::vector<std::array<uint32_t, 3>>& triangles,
                            unsigned mask) {
        RTCGeometry geom = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // rtcSetNewGeometryBuffer allocates with the padding Embree's 16-byte loads need.
        auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), vertices.size()));
        for (size_t i = 0; i < vertices.size(); ++i)
            for (int a = 0; a < 3; ++a) vb[3 * i + a] = static_cast<float>(vertices[i][a]);
        auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(unsigned), triangles.size()));
        for (size_t i = 0; i < triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) ib[3 * i + k] = triangles[i][k];
        rtcSetGeometryMask(geom, mask);
        rtcCommitGeometry(geom);
        unsigned id = rtcAttachGeometry(m_impl->scene, geom);
        rtcReleaseGeometry(geom);
        return id;
    };
    std::vector<std::array<uint32_t, 3>> patchTriangles;
    patchTriangles.reserve(mesh.patches.size());
    for (const auto& p : mesh.patches) patchTriangles.push_back({p.v[0], p.v[1], p.v[2]});
    if (!patchTriangles.empty()) m_impl->patchGeometry = addTriangles(mesh.vertices, patchTriangles, kOpaqueMask);
    if (!patchTriangles.empty()) {
        m_impl->normals.reserve(mesh.patches.size());
        for (const auto& p : mesh.patches) m_impl->normals.push_back(glm::vec3(p.normal));
        RTCGeometry geom = rtcGetGeometry(m_impl->scene, m_impl->patchGeometry);
        rtcSetGeometryUserData(geom, m_impl.get());
        rtcSetGeometryIntersectFilterFunction(geom, frontFacesOnly);
        rtcCommitGeometry(geom);
    }
    for (bool glass : {false, true}) {
        std::vector<Vec3> vertices;
        std::vector<std::array<uint32_t, 3>> triangles;
        std::vector<uint32_t>& index = glass ? m_impl->glassIndex : m_impl->mirrorIndex;
        for (uint32_t i = 0; i < specular.size(); ++i) {
            if (specular[i].glass != glass) continue;
            auto base = static_cast<uint32_t>(vertices.size());
            for (const auto& v : specular[i].v) vertices.push_back(v);
            triangles.push_back({base, base + 1, base + 2});
            index.push_back(i);
        }
        if (triangles.empty()) continue;
        unsigned id = addTriangles(vertices, triangles, glass ? kGlassMask : kOpaqueMask);
        (glass ? m_impl->glassGeometry : m_impl->mirrorGeometry) = id;
    }
    rtcCommitScene(m_impl->scene);
    if (!m_impl->error.empty()) throw InternalError(m_impl->error);

    // What blocks visibility: the patches and the mirrors (glass lets it through).
    std::vector<std::array<Vec3, 3>> occluders;
    std::vector<Vec3> normals;
    for (const auto& p : mesh.patches) {
        occluders.push_back({mesh.vertices[p.v[0]], mesh.vertices[p.v[1]], mesh.vertices[p.v[2]]});
        normals.push_back(p.normal);
    }
    for (const auto& t : specular)
        if (!t.glass) occluders.push_back(t.v), normals.push_back(t.normal);
    m_enclosure = ConvexEnclosure(occluders, normals, 1e-4 * epsilon);
}

EmbreeScene::~EmbreeScene() = default;

bool EmbreeScene::visible(const Vec3& from, const Vec3& to) const { return !occluded(from, to, m_epsilon); }

bool EmbreeScene::visibleFromSurface(const Vec3& x, const Vec3& n, const Vec3& to) const {
    return !occluded(x + m_epsilon * n, to, 0.0);  // lifted off the surface, not shrunk there
}

bool EmbreeScene::backCovered(const Vec3& x, const Vec3& n) const {
    // From just behind x toward its back: a front face met within a few epsilons faces −n
    // (x's own patch is met from behind and passed).
    const double window = 4 * m_epsilon;
    Hit h = intersect(x - window * n, n, 0.0, 2 * window, /*frontOnly=*/true);
    return h.found && !h.specular;
}

bool EmbreeScene::hitsBackFace(const Vec3& from, const Vec3& direction) const {
    const Hit h = intersect(from, direction, 0.0, std::numeric_limits<double>::infinity());
    return h.found && !h.specular && glm::dot(direction, Vec3(m_impl->normals[h.patch])) > 0;
}

bool EmbreeScene::patchesNear(const Vec3& x, double radius, const std::function<void(uint32_t)>& visit) const {
    struct Visit {
        unsigned patchGeometry;
        const std::function<void(uint32_t)>* visit;
    } user{m_impl->patchGeometry, &visit};
    RTCPointQuery query{};
    query.x = static_cast<float>(x.x);
    query.y = static_cast<float>(x.y);
    query.z = static_cast<float>(x.z);
    query.radius = static_cast<float>(radius + m_epsilon);  // the BVH's bounds are float
    query.time = 0;
    RTCPointQueryContext context;
    rtcInitPointQueryContext(&context);
    // Called for each primitive whose bounds overlap the query's ball.
    auto onPrimitive = [](RTCPointQueryFunctionArguments* args) {
        const auto* u = static_cast<const Visit*>(args->userPtr);
        if (args->geomID == u->patchGeometry) (*u->visit)(args->primID);
        return false;  // the ball is not shrunk
    };
    rtcPointQuery(m_impl->scene, &query, &context, onPrimitive, &user);
    return true;
}

namespace {
/// A shadow ray's segment as Embree takes it (single precision): origin, unit direction,
/// and the open interval (tnear, tfar). `empty`: nothing to test (no length left).
struct ShadowSegment {
    float org[3], dir[3], tnear, tfar;
    bool empty;
};

ShadowSegment shadowSegment(const Vec3& from, const Vec3& to, double startShrink, double epsilon) {
    ShadowSegment s{};
    const Vec3 d = to - from;
    const double len = glm::length(d);
    s.empty = len <= 2 * startShrink;
    if (s.empty) return s;
    // The end at `to` (a point on a surface) is shrunk by the epsilon, or by half the
    // length for segments shorter than that: a 10 µm segment from a point at the foot of
    // a wall to the floor beyond it must still meet the wall.
    const double endShrink = std::min(epsilon, 0.5 * (len - startShrink));
    for (int k = 0; k < 3; ++k) {
        s.org[k] = static_cast<float>(from[k]);
        s.dir[k] = static_cast<float>(d[k] / len);
    }
    s.tnear = static_cast<float>(startShrink);
    s.tfar = static_cast<float>(len - endShrink);
    return s;
}

/// One segment, one ray (rtcOccluded1).
bool occludedSegment(RTCScene scene, const ShadowSegment& s) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = s.org[0], ray.org_y = s.org[1], ray.org_z = s.org[2];
    ray.dir_x = s.dir[0], ray.dir_y = s.dir[1], ray.dir_z = s.dir[2];
    ray.tnear = s.tnear;
    ray.tfar = s.tfar;
    ray.mask = kOpaqueMask;  // Debian's Embree has ray masks on: glass (mask 2) lets light through
    ray.flags = 0;
    rtcOccluded1(scene, &context, &ray);
    return ray.tfar < 0;  // an occluder sets tfar to -inf
}

/// Up to W shadow segments (W = 4 or 8) as one Embree packet: visible[i] for segments[i].
template <int W, class RayW>
void occludedPacket(RTCScene scene, RTCIntersectContext& context, const ShadowSegment* segments, size_t count,
                    bool* visible, void (*trace)(const int*, RTCScene, RTCIntersectContext*, RayW*)) {
    alignas(64) int valid[W] = {};
    alignas(64) RayW rays{};
    bool any = false;
    for (size_t lane = 0; lane < count; ++lane) {
        const ShadowSegment& s = segments[lane];
        if (s.empty) continue;
        valid[lane] = -1, any = true;
        rays.org_x[lane] = s.org[0], rays.org_y[lane] = s.org[1], rays.org_z[lane] = s.org[2];
        rays.dir_x[lane] = s.dir[0], rays.dir_y[lane] = s.dir[1], rays.dir_z[lane] = s.dir[2];
        rays.tnear[lane] = s.tnear, rays.tfar[lane] = s.tfar;
        rays.mask[lane] = kOpaqueMask;
    }
    if (any) trace(valid, scene, &context, &rays);
    for (size_t lane = 0; lane < count; ++lane)
        visible[lane] = !valid[lane] || !(rays.tfar[lane] < 0);  // an occluder sets tfar to -inf
}
}  // namespace

void EmbreeScene::visibleFromSurfaceMany(const Vec3& x, const Vec3& n, const Vec3* to, size_t count,
                                         bool* visible) const {
    const Vec3 from = x + m_epsilon * n;  // as visibleFromSurface: lifted off, not shrunk there
    const bool fromInside = m_enclosure.contains(from);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // one origin, nearby targets
    for (size_t first = 0; first < count; first += 8) {
        const size_t lanes = std::min<size_t>(8, count - first);
        ShadowSegment segments[8];
        for (size_t lane = 0; lane < lanes; ++lane) {
            segments[lane] = shadowSegment(from, to[first + lane], 0.0, m_epsilon);
            if (fromInside && m_enclosure.contains(to[first + lane])) segments[lane].empty = true;  // nothing between
        }
        if (lanes == 1)
            visible[first] = segments[0].empty || !occludedSegment(m_impl->scene, segments[0]);
        else if (lanes <= 4)
            occludedPacket<4, RTCRay4>(m_impl->scene, context, segments, lanes, visible + first, rtcOccluded4);
        else
            occludedPacket<8, RTCRay8>(m_impl->scene, context, segments, lanes, visible + first, rtcOccluded8);
    }
}

bool EmbreeScene::occluded(const Vec3& from, const Vec3& to, double startShrink) const {
    if (m_enclosure.contains(from) && m_enclosure.contains(to)) return false;  // nothing can lie between
    const ShadowSegment s = shadowSegment(from, to, startShrink, m_epsilon);
    return !s.empty && occludedSegment(m_impl->scene, s);
}

Hit EmbreeScene::intersect(const Vec3& origin, const Vec3& dir, double tnear, double tfar, bool frontOnly) const {
    QueryContext query;
    rtcInitIntersectContext(&query.base);
    query.frontOnly = frontOnly;
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(origin.x);
    rh.ray.org_y = static_cast<float>(origin.y);
    rh.ray.org_z = static_cast<float>(origin.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    // Embree requires 0 <= tnear (its debug builds assert it): a window around a hit
    // at the ray's origin, such as the back-face test's, starts at the origin.
    rh.ray.tnear = static_cast<float>(std::max(0.0, tnear));
    rh.ray.tfar = std::isfinite(tfar) ? static_cast<float>(tfar) : std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_impl->scene, &query.base, &rh);
    Hit h;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    h.found = true;
    if (rh.hit.geomID == m_impl->patchGeometry) {
        h.patch = rh.hit.primID;
    } else {
        h.specular = true;
        h.patch = (rh.hit.geomID == m_impl->glassGeometry ? m_impl->glassIndex : m_impl->mirrorIndex)[rh.hit.primID];
    }
    h.u = rh.hit.u;
    h.v = rh.hit.v;
    h.t = rh.ray.tfar;
    return h;
}

std::unique_ptr<EmbreeScene> buildEmbreeScene(const scene::Scene& scene, const radiosity::PatchMesh& mesh) {
    return std::make_unique<EmbreeScene>(mesh, 1e-5 * scene.diagonal(), specularTriangles(scene));
}

std::string embreeVersion() { return "Embree " RTC_VERSION_STRING; }

}  // namespace rayrad::raytrace
