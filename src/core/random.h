// A small deterministic random number generator (PCG32), so results depend only on the seed.
#pragma once

#include <cstdint>

namespace rayrad {

/// PCG32 (O'Neill 2014). Streams let every pixel or patch have its own sequence,
/// so results do not depend on the number of threads.
class Random {
  public:
    explicit Random(uint64_t seed, uint64_t stream = 0) {
        m_inc = (stream << 1u) | 1u;
        nextUint();
        m_state += seed;
        nextUint();
    }

    uint32_t nextUint() {
        uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_inc;
        auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }

    /// Uniform in [0, 1).
    double nextDouble() { return nextUint() * (1.0 / 4294967296.0); }

  private:
    uint64_t m_state = 0x853c49e6748fea9bULL;
    uint64_t m_inc = 0xda3e39cb94b95bdbULL;
};

}  // namespace rayrad
