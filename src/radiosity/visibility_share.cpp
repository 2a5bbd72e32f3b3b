#include <radiosity/visibility_share.h>

#include <algorithm>
#include <cmath>
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
    int nearest = 0;
    for (int i = 1; i < 4; ++i)
        if (std::abs(kVisibilityFractions[i] - q) < std::abs(kVisibilityFractions[nearest] - q)) nearest = i;
    return (*m_members)[it->node->rayTo[nearest]];
}

}  // namespace rayrad::radiosity
