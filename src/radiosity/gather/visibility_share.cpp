#include <radiosity/gather/visibility_share.h>

#include <core/random.h>

#include <algorithm>
#include <cstring>
#include <iterator>

namespace rayrad::radiosity {

uint32_t ClusterVisibility::patchAt(double target) const {
    auto it = std::lower_bound(m_entries.begin(), m_entries.end(), target,
                               [](const Entry& e, double t) { return e.end < t; });
    if (it == m_entries.end()) --it;  // rounding at the top
    if (!it->node) return it->patch;
    // Where in the node's own light the target falls, and its power sample nearest there.
    const double begin = it == m_entries.begin() ? 0.0 : std::prev(it)->end;
    const double q = (target - begin) / (it->end - begin);
    const int nearest = std::clamp(static_cast<int>(q * 4), 0, 3);  // rayTo[i] at (i + ½)/4
    return (*m_members)[it->node->rayTo[nearest]];
}

double visibilityOffset(const Vec3& x, uint64_t image, uint64_t source) {
    uint64_t seed = image;
    for (int k = 0; k < 3; ++k) {
        uint64_t bits;
        std::memcpy(&bits, &x[k], sizeof bits);
        seed = (seed ^ bits) * 0x9e3779b97f4a7c15ULL;
    }
    return Random(seed, source).nextDouble();
}

uint64_t imageKey(const std::vector<int>& chain) {
    uint64_t key = 1;
    for (int m : chain) key = key * 1000003 + static_cast<uint64_t>(m) + 1;
    return key;
}

}  // namespace rayrad::radiosity
