// Visibility rays from one surface point, traced together: each ray carries the light it
// would let through, and the light of the rays that are not blocked is summed.
#pragma once

#include <core/visibility.h>

#include <cstddef>

namespace rayrad {

/// Collects rays from x (on a surface with unit normal n) toward targets, each with a
/// value T (light, lx, or a weight), and traces them kSize at a time with
/// Visibility::visibleFromSurfaceMany (Embree: one packet of eight). The values of the
/// visible ones are added to `sum` in the order they were added; call flush() before
/// reading `sum`.
template <class T, size_t kSize = 8>
class RayBatch {
  public:
    RayBatch(const Visibility& vis, const Vec3& x, const Vec3& n, T& sum) : m_vis(vis), m_x(x), m_n(n), m_sum(sum) {}
    void add(const Vec3& target, const T& value) {
        m_targets[m_count] = target;
        m_values[m_count] = value;
        if (++m_count == kSize) flush();
    }
    void flush() {
        if (m_count == 0) return;
        bool visible[kSize];
        m_vis.visibleFromSurfaceMany(m_x, m_n, m_targets, m_count, visible);
        for (size_t i = 0; i < m_count; ++i)
            if (visible[i]) m_sum += m_values[i];
        m_count = 0;
    }

  private:
    const Visibility& m_vis;
    const Vec3 m_x, m_n;
    T& m_sum;
    Vec3 m_targets[kSize];
    T m_values[kSize];
    size_t m_count = 0;
};

}  // namespace rayrad
