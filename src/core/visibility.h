// The ray-casting interface the radiosity solver and the ray tracer share (Embree behind it).
#pragma once

#include <core/math.h>

#include <cstdint>
#include <functional>

namespace rayrad {

/// Answers "can these two points see each other?" for the scene's geometry. The two
/// ends are surface points; implementations shrink the segment by a scene-relative
/// epsilon so a surface does not occlude itself.
class Visibility {
  public:
    virtual ~Visibility() = default;
    /// True when nothing blocks the open segment between `from` and `to` (metres).
    virtual bool visible(const Vec3& from, const Vec3& to) const = 0;
    /// The same from a point x on a surface with unit normal n: the segment leaves from
    /// x lifted off its surface, and is not shrunk at that end. (A segment shrunk along
    /// itself from a point where a wall stands on the floor starts beyond the wall: the
    /// light behind the wall leaked in.) x should lie inside its own patch, not on an edge.
    virtual bool visibleFromSurface(const Vec3& x, const Vec3& /*n*/, const Vec3& to) const { return visible(x, to); }
    /// visibleFromSurface(x, n, to[i]) into visible[i] for i < count: the same answers,
    /// but an implementation may trace them together (Embree: packets of four or eight;
    /// rays from one point toward a compact group of targets are coherent). RayBatch
    /// (core/ray_batch.h) collects them.
    virtual void visibleFromSurfaceMany(const Vec3& x, const Vec3& n, const Vec3* to, size_t count, bool* visible) const {
        for (size_t i = 0; i < count; ++i) visible[i] = visibleFromSurface(x, n, to[i]);
    }
    /// True when another surface's front coincides with the surface at x (unit normal n)
    /// and faces the other way, −n: back-to-back surfaces (a zero-thickness wall), where
    /// nothing reaches x's back — the light there lands on the other surface's front.
    virtual bool backCovered(const Vec3& /*x*/, const Vec3& /*n*/) const { return false; }
    /// True when the first surface the ray from `from` along `direction` meets is seen
    /// from behind (a point inside a closed solid sees only backs). False when it meets
    /// nothing, a front, or this visibility cannot tell.
    virtual bool hitsBackFace(const Vec3& /*from*/, const Vec3& /*direction*/) const { return false; }
    /// Calls visit(i) for every radiosity patch i whose bounds come within `radius` (m) of
    /// x, and maybe a few more, in no particular order. False when this visibility has no
    /// spatial index: the caller must then look at every patch.
    virtual bool patchesNear(const Vec3& /*x*/, double /*radius*/, const std::function<void(uint32_t)>& /*visit*/) const {
        return false;
    }
};

}  // namespace rayrad
