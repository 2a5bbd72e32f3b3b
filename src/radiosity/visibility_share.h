// How much of a source's light reaches a point in the final gather when its visibility
// is sampled, not traced member by member: a far member-tree node (FarSource::rayTo) or a
// far cluster whose members share their rays. Both sample where the light is: at four
// points stratified by light, two rays first, the other two only when those two disagree
// (most sources are wholly seen or wholly hidden: two rays). A re-gather (weight < 1)
// takes the first sample alone.
//
// One ray toward the brightest member (before 2026-11-26) is biased where the light
// and the occluders are correlated: on the hall's ceiling, past rows of desks, the floor's
// members the troffers light are the ones the ceiling sees, and the sensors read 3-7 %
// high (docs/validation.md, "Far sources' visibility"). The shooting's far nodes keep
// that one ray: against every member's own ray (the hall's patches, 95th percentile) it
// is 0.42 % off, up to four sampled rays 0.42 % at 13 % more shooting CPU, one sample
// at 3/8 of the power 0.51 %.
#pragma once

#include <radiosity/far_field.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// Where the four samples lie: at (i + u)/4 of the light, i = 0 … 3, u an offset in
/// [0, 1) drawn per source and point (visibilityOffset), tried in the order i = 0, 2, 1, 3
/// (the first two in opposite halves). With fixed samples the hall's ceiling sensors
/// read −0.5 … +0.6 % (1/8 and 5/8 tried first) or +0.3 … +2.8 % (3/8 and 7/8) of every
/// patch's own ray: in a regular room the sources' errors line up with the rows of
/// desks. Drawn, they do not (+0.7 … +1.3 %).
constexpr std::array<int, 4> kVisibilityOrder = {0, 2, 1, 3};

/// How many rays a source's visibility may take: `One` (the first sample only, for
/// work whose error reaches the result diminished) or `UpToFour`.
enum class VisibilityRays { One, UpToFour };

/// The share (0 … 1) seen of four stratified samples; `seen(i)` traces sample
/// kVisibilityOrder[i]. Two rays first; the other two only when those disagree.
template <class Seen>
double stratifiedShare(Seen&& seen, VisibilityRays rays) {
    const bool a = seen(0);
    if (rays == VisibilityRays::One) return a ? 1.0 : 0.0;
    const bool b = seen(1);
    if (a == b) return a ? 1.0 : 0.0;
    return 0.25 * (1 + int(seen(2)) + int(seen(3)));  // a + b = 1
}

/// The offset u in [0, 1) of source `source` (a cluster, or a node of one) seen from x:
/// the same for the same point, so results do not depend on threads or order.
double visibilityOffset(const Vec3& x, uint64_t source);

/// The share of a far node's light that reaches a point: `visible(k)` for its samples,
/// member positions k stratified by power (FarSource::rayTo at 1/8, 3/8, 5/8, 7/8 of it;
/// u < ½ takes the pairs 1/8 & 5/8 first, else 3/8 & 7/8).
template <class Visible>
double visibleShare(const FarSource& f, Visible&& visible, VisibilityRays rays, double u) {
    const int turn = u < 0.5 ? 0 : 1;
    return stratifiedShare([&](int i) { return visible(f.rayTo[(kVisibilityOrder[i] + turn) % 4]); }, rays);
}

/// A far cluster's light at one point, gathered contribution by contribution (a
/// member's, or a far node's) in member-tree order, with its visibility sampled at the
/// end: four samples stratified by contribution (what the point receives, so the
/// cosines and distances count, not only the power). A sample that falls in a far
/// node's contribution at a fraction q of it takes the node's power sample nearest q.
/// Reused for cluster after cluster (start clears it).
class ClusterVisibility {
  public:
    /// A new cluster, whose members (Cluster::patches) far nodes' positions refer to.
    void start(const std::vector<uint32_t>& members) {
        m_members = &members;
        m_entries.clear();
        m_total = 0;
    }
    /// Contribution e (its luminance, lx) of `patch`, seen along the ray to its centroid.
    void addPatch(double e, uint32_t patch) { add(e, patch, nullptr); }
    /// Contribution e of far node f, seen along the rays to its samples.
    void addNode(double e, const FarSource& f) { add(e, 0, &f); }
    /// The share seen; `visible(patch)` traces the ray to that patch's centroid.
    template <class Visible>
    double share(Visible&& visible, VisibilityRays rays, double u) const {
        if (!(m_total > 0)) return 0;
        return stratifiedShare([&](int i) { return visible(patchAt((kVisibilityOrder[i] + u) / 4 * m_total)); }, rays);
    }

  private:
    struct Entry {
        double end;             ///< running sum of the contributions up to and with this one
        uint32_t patch;         ///< the patch, for a patch's contribution
        const FarSource* node;  ///< the node, for a far node's (or null)
    };
    void add(double e, uint32_t patch, const FarSource* node) {
        if (!(e > 0)) return;
        m_total += e;
        m_entries.push_back({m_total, patch, node});
    }
    /// The patch where the running sum reaches `target`.
    uint32_t patchAt(double target) const;

    const std::vector<uint32_t>* m_members = nullptr;
    std::vector<Entry> m_entries;
    double m_total = 0;
};

}  // namespace rayrad::radiosity
