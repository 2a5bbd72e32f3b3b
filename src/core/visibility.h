// The ray-casting interface the radiosity solver and the ray tracer share (Embree behind it).
#pragma once

#include <core/math.h>

namespace rayrad {

/// Answers "can these two points see each other?" for the scene's geometry. The two
/// ends are surface points; implementations shrink the segment by a scene-relative
/// epsilon so a surface does not occlude itself.
class Visibility {
  public:
    virtual ~Visibility() = default;
    /// True when nothing blocks the open segment between `from` and `to` (metres).
    virtual bool visible(const Vec3& from, const Vec3& to) const = 0;
};

}  // namespace rayrad
