// How much of a source's light reaches a point when its visibility is sampled, not
// traced member by member: a far member-tree node (FarSource::rayTo) or a far cluster
// whose members share their rays (the final gather). Both sample where the light is:
// at four points stratified by light, two rays first, the other two only when those two
// disagree (most sources are wholly seen or wholly hidden: two rays).
//
// One ray toward the brightest member (before 2026-11-26) is biased where the light
// and the occluders are correlated: on the hall's ceiling, past rows of desks, the floor's
// members the troffers light are the ones the ceiling sees, and the sensors read 3-7 %
// high (docs/validation.md, "Far sources' visibility").
#pragma once

#include <radiosity/far_field.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// The sampling points as fractions of the light, in the order they are tried: the first
/// two in opposite halves.
constexpr std::array<double, 4> kVisibilityFractions = {0.125, 0.625, 0.375, 0.875};

/// The share (0 … 1) seen of four stratified samples; `seen(i)` traces sample i (at
/// kVisibilityFractions[i] of the light).
template <class Seen>
double stratifiedShare(Seen&& seen) {
    const bool a = seen(0), b = seen(1);
    if (a == b) return a ? 1.0 : 0.0;
    return 0.25 * (1 + int(seen(2)) + int(seen(3)));  // a + b = 1
}

/// The share of a far node's light that reaches a point: `visible(k)` for its samples,
/// member positions k stratified by power.
template <class Visible>
double visibleShare(const FarSource& f, Visible&& visible) {
    return stratifiedShare([&](int i) { return visible(f.rayTo[i]); });
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
    double share(Visible&& visible) const {
        if (!(m_total > 0)) return 0;
        return stratifiedShare([&](int i) { return visible(patchAt(kVisibilityFractions[i] * m_total)); });
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
