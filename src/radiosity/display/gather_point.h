// A mesh vertex whose display value comes from a point gather, and where it is gathered.
#pragma once

#include <core/math.h>

#include <cstddef>

namespace rayrad::radiosity {

/// A vertex whose indirect value is gathered at `at` (on its surface, normal `normal`).
struct GatherPoint {
    size_t vertex = 0;
    Vec3 at{0.0};
    Vec3 normal{0.0};
};

}  // namespace rayrad::radiosity
