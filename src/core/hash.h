// A 64-bit FNV-1a hash of plain values: what saved solutions and render tiles fingerprint
// their inputs with (not a checksum against forgery).
#pragma once

#include <core/math.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

namespace rayrad {

/// 64-bit FNV-1a over values' bytes.
class Hash {
  public:
    void bytes(const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) m_h = (m_h ^ p[i]) * 1099511628211ull;
    }
    template <class T>
    Hash& operator<<(const T& v) {
        static_assert(std::is_arithmetic_v<T>, "hash numbers only (no padding)");
        bytes(&v, sizeof v);
        return *this;
    }
    Hash& operator<<(const Vec3& v) { return *this << v.x << v.y << v.z; }
    Hash& operator<<(const std::string& s) {
        *this << s.size();
        bytes(s.data(), s.size());
        return *this;
    }
    uint64_t value() const { return m_h; }

  private:
    uint64_t m_h = 14695981039346656037ull;
};

}  // namespace rayrad
