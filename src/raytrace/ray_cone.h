// A ray's footprint as a cone (Akenine-Möller et al. 2019, "Texture Level of Detail
// Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20): the width a pixel sample
// covers grows along the ray as w(t) = w0 + γ t. At a textured hit the footprint chooses
// the texture's MIP level, so a fine pattern far away is averaged instead of aliased.
#pragma once

#include <core/math.h>

#include <utility>

namespace rayrad::raytrace {

struct RayCone {
    double width = 0;   ///< w0 at the ray's origin, m
    double spread = 0;  ///< γ, radians: how fast the width grows with distance

    double widthAt(double distance) const { return width + spread * distance; }
    /// The cone after a planar mirror or glass surface at `distance`: the width it has
    /// there, the same spread (a flat interface neither focuses nor spreads it).
    RayCone continuedAt(double distance) const { return {widthAt(distance), spread}; }
};

/// The two axes (world space, m) of the ellipse a cone of width w makes on a surface with
/// unit normal n, hit along the unit direction d: w / |cos θ| along d's projection onto
/// the surface, w across it. The stretch is capped at 32 (OIIO's largest anisotropy); at
/// normal incidence the first axis is any direction in the plane.
std::pair<Vec3, Vec3> surfaceFootprint(double width, const Vec3& d, const Vec3& n);

}  // namespace rayrad::raytrace
