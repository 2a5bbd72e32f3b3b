// The value a solve carries per patch: one grey channel (double) or three (Rgb).
#pragma once

#include <core/math.h>

namespace rayrad::radiosity {

/// Luminance weight Y of a light value (a grey value is its own Y).
inline double lum(double v) { return v; }
inline double lum(const Rgb& v) { return luminance(v); }

/// From the solution's RGB storage into the solve's value (grey: Y; the scene is grey).
template <class V>
V fromRgb(const Rgb& c);
template <>
inline double fromRgb<double>(const Rgb& c) { return luminance(c); }
template <>
inline Rgb fromRgb<Rgb>(const Rgb& c) { return c; }

/// Back into RGB storage.
inline Rgb toRgb(double v) { return Rgb(v); }
inline Rgb toRgb(const Rgb& v) { return v; }

}  // namespace rayrad::radiosity
