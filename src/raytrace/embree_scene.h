// Embree 3 behind a small interface: visibility for the radiosity, hits for the ray tracer.
#pragma once

#include <core/visibility.h>
#include <radiosity/patch_mesh.h>

#include <memory>

namespace rayrad::raytrace {

/// The nearest surface along a ray: patch index, barycentrics (1-u-v, u, v), distance.
struct Hit {
    bool found = false;
    uint32_t patch = 0;
    double u = 0, v = 0, t = 0;
};

/// One Embree device and scene over the patch triangles (RAII). Thread-safe queries.
class EmbreeScene : public Visibility {
  public:
    /// `epsilon` (metres) shrinks visibility segments at both ends; pass about 1e-5 of
    /// the scene diagonal so results do not depend on the scene's scale.
    EmbreeScene(const radiosity::PatchMesh& mesh, double epsilon);
    ~EmbreeScene() override;
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    bool visible(const Vec3& from, const Vec3& to) const override;
    /// Nearest hit along origin + t·dir for t in (tnear, tfar); dir need not be unit.
    Hit intersect(const Vec3& origin, const Vec3& dir, double tnear, double tfar) const;
    double epsilon() const { return m_epsilon; }

  private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    double m_epsilon;
};

}  // namespace rayrad::raytrace
