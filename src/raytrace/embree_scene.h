// Embree 3 behind a small interface: visibility for the radiosity, hits for the ray tracer.
#pragma once

#include <core/visibility.h>
#include <raytrace/convex_enclosure.h>

#include <radiosity/radiosity.h>
#include <scene/scene.h>
#include <string>

#include <array>
#include <memory>
#include <vector>

namespace rayrad::raytrace {

/// A triangle of a mirror or glass surface: in the ray tracer, not in the radiosity mesh.
struct SpecularTriangle {
    std::array<Vec3, 3> v;
    Vec3 normal{0.0};  ///< unit, front side
    int material = 0;
    bool glass = false;  ///< glass (clear to visibility) or mirror (opaque)
};

/// The triangles of every mirror and glass surface.
std::vector<SpecularTriangle> specularTriangles(const scene::Scene& scene);

/// The nearest surface along a ray: a patch (index, barycentrics (1-u-v, u, v)) or a
/// specular triangle (index), and the distance.
struct Hit {
    bool found = false;
    bool specular = false;  ///< index is into the specular triangles, not the patches
    uint32_t patch = 0;     ///< patch or specular triangle index
    double u = 0, v = 0, t = 0;
};

/// One Embree device and scene over the patch triangles and the specular triangles
/// (RAII). Thread-safe queries. Visibility (shadow rays, radiosity) sees patches and
/// mirrors but not glass: glass is clear to the radiosity and casts no shadow (a ray
/// mask, geometry mask 2); intersect() sees everything.
class EmbreeScene : public Visibility {
  public:
    /// `epsilon` (metres) shrinks visibility segments at both ends; pass about 1e-5 of
    /// the scene diagonal so results do not depend on the scene's scale.
    EmbreeScene(const radiosity::PatchMesh& mesh, double epsilon, const std::vector<SpecularTriangle>& specular = {});
    ~EmbreeScene() override;
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    bool visible(const Vec3& from, const Vec3& to) const override;
    bool visibleFromSurface(const Vec3& x, const Vec3& n, const Vec3& to) const override;
    void visibleFromSurfaceMany(const Vec3& x, const Vec3& n, const Vec3* to, size_t count,
                                bool* visible) const override;
    bool backCovered(const Vec3& x, const Vec3& n) const override;
    bool hitsBackFace(const Vec3& from, const Vec3& direction) const override;
    bool patchesNear(const Vec3& x, double radius, const std::function<void(uint32_t)>& visit) const override;
    /// Nearest hit along origin + t·dir for t in (tnear, tfar); dir need not be unit.
    /// `frontOnly`: patches' back faces are passed (to find a coincident front face).
    Hit intersect(const Vec3& origin, const Vec3& dir, double tnear, double tfar, bool frontOnly = false) const;
    double epsilon() const { return m_epsilon; }
    const SpecularTriangle& specular(uint32_t i) const { return m_specular[i]; }
    /// The planes of the scene when it is one convex enclosure (shadow rays between points
    /// inside it are not traced), else empty.
    const ConvexEnclosure& convexEnclosure() const { return m_enclosure; }

    struct Impl;

  private:
    /// Is the segment blocked, shrunk by `startShrink` at `from` and by the epsilon at `to`?
    bool occluded(const Vec3& from, const Vec3& to, double startShrink) const;

    std::unique_ptr<Impl> m_impl;
    double m_epsilon;
    std::vector<SpecularTriangle> m_specular;
    ConvexEnclosure m_enclosure;
};

/// The scene's patches and specular triangles, with the visibility epsilon at 1e-5 of
/// the scene diagonal (results do not depend on the scene's scale).
std::unique_ptr<EmbreeScene> buildEmbreeScene(const scene::Scene& scene, const radiosity::PatchMesh& mesh);

/// "Embree 3.13.5": the version this build uses.
std::string embreeVersion();

}  // namespace rayrad::raytrace
