// Disjoint sets (union–find with path halving): which of n items a relation joins.
#pragma once

#include <cstddef>
#include <numeric>
#include <vector>

namespace rayrad {

/// Items 0 … n−1, each in a set of its own until joined.
class DisjointSets {
  public:
    explicit DisjointSets(size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), size_t(0)); }
    /// The representative of a's set.
    size_t find(size_t a) {
        while (m_parent[a] != a) a = m_parent[a] = m_parent[m_parent[a]];
        return a;
    }
    void join(size_t a, size_t b) { m_parent[find(a)] = find(b); }

  private:
    std::vector<size_t> m_parent;
};

}  // namespace rayrad
