// The value a solve carries per patch: one grey channel (double) or three (Rgb).
#pragma once

#include <core/math.h>

namespace rayrad::radiosity {

/// Luminance weight Y of a light value (a grey value is its own Y).
inline double lum(double v) {
    return v;
}
inline double lum(const Rgb& v) {
    return luminance(v);
}

/// From the solution's RGB storage into the solve's value (grey: Y; the scene is grey).
template <class V>
V fromRgb(const Rgb& c);
template <>
inline double fromRgb<double>(const Rgb& c) {
    return luminance(c);
}
template <>
inline Rgb fromRgb<Rgb>(const Rgb& c) {
    return c;
}

/// Light delivered through mirrors of weight w = Π Ks, as it left its source: delivered / w,
/// per channel (a channel the mirrors do not reflect delivers none).
inline double atSource(double delivered, double w) {
    return w > 0 ? delivered / w : 0.0;
}
inline Rgb atSource(const Rgb& delivered, const Rgb& w) {
    return {atSource(delivered.r, w.r), atSource(delivered.g, w.g), atSource(delivered.b, w.b)};
}
/// What those mirrors absorbed of it: delivered · (1/w − 1).
template <class V>
V mirrorLoss(const V& delivered, const V& w) {
    return atSource(delivered, w) - delivered;
}

/// Back into RGB storage.
inline Rgb toRgb(double v) {
    return Rgb(v);
}
inline Rgb toRgb(const Rgb& v) {
    return v;
}

}  // namespace rayrad::radiosity
