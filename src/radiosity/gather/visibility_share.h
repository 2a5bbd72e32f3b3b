// How much of a source's light reaches a point in the final gather when its visibility
// is sampled, not traced member by member: a far member-tree node (FarSource::rayTo) or a
// far cluster whose members share their rays. Both sample where the light is: at four
// points stratified by light. A gather that knows roughly what the point will receive
// gives the sources that bring at least 1/1000 of it all four rays and the rest the first
// alone; one that does not, two rays first and the other two only when those two disagree
// (most sources are wholly seen or wholly hidden: two rays). A re-gather (weight < 1)
// takes the first sample alone.
//
// One ray toward the brightest member is biased where the light and the occluders are
// correlated: on the hall's ceiling, past rows of desks, the floor's members the troffers
// light are the ones the ceiling sees, and the sensors read 3-7 % high. The shooting's far
// nodes take the four samples too, each ray letting a quarter of the node's light through.
#pragma once

#include <radiosity/clusters/far_field.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// How many rays a source's visibility takes: `One`, at a fraction u of its light drawn
/// per point and source (visibilityOffset) — an unbiased estimate of the share seen,
/// whose errors average out over many sources; `Four`, one in each stratum — unbiased,
/// of lower variance, for the sources that bring a point much of its light; or
/// `UpToFour`: two, and two more when those disagree, as cheap as two for the many
/// sources wholly seen or hidden but biased a little high (two rays that agree miss a
/// small hidden part), for a gather that does not know which sources matter.
enum class VisibilityRays { One, UpToFour, Four };

/// Sample j (0 … 3) of a source whose offset is u: the stratum (⌊4u⌋ + {0, 2, 1, 3}[j])
/// mod 4 of four equal ones, at the same place 4u − ⌊4u⌋ within it. Sample 0 lies at u
/// itself; samples 0 and 1 lie in opposite halves. (Fixed samples, the same u for every
/// point and source, line up with a regular room's rows of desks: which pair the hall
/// tried first moved its ceiling sensors by 2 %; docs/validation.md.)
struct VisibilitySamples {
    explicit VisibilitySamples(double u) : first(std::min(3, static_cast<int>(4 * u))), within(4 * u - first) {}
    int stratum(int j) const { return (first + kOrder[j]) % 4; }
    double fraction(int j) const { return (stratum(j) + within) / 4; }
    static constexpr std::array<int, 4> kOrder = {0, 2, 1, 3};
    int first;
    double within;
};

/// The share (0 … 1) seen; `seen(j)` traces sample j. With UpToFour two rays first, the
/// other two only when those disagree.
template <class Seen>
double stratifiedShare(Seen&& seen, VisibilityRays rays) {
    const bool a = seen(0);
    if (rays == VisibilityRays::One) return a ? 1.0 : 0.0;
    const bool b = seen(1);
    if (a == b && rays == VisibilityRays::UpToFour) return a ? 1.0 : 0.0;
    return 0.25 * (int(a) + int(b) + int(seen(2)) + int(seen(3)));
}

/// The offset u in [0, 1) of source `source` (a cluster, or a node of one) in mirror
/// image `image` (0 for the scene itself; see imageKey) seen from x: the same for the same
/// point and source, so results depend neither on threads nor on order, nor on which
/// other images a run keeps.
double visibilityOffset(const Vec3& x, uint64_t image, uint64_t source);

/// A mirror image's key for visibilityOffset, from its chain of mirrors (indices into
/// Scene::mirrors): never 0, the key of the scene itself.
uint64_t imageKey(const std::vector<int>& chain);

/// The share of a far node's light that reaches a point: `visible(k)` for its samples,
/// member positions k stratified by power (FarSource::rayTo at 1/8, 3/8, 5/8, 7/8 of it:
/// sample j takes the one of its stratum).
template <class Visible>
double visibleShare(const FarSource& f, Visible&& visible, VisibilityRays rays, double u) {
    const VisibilitySamples samples(u);
    return stratifiedShare([&](int j) { return visible(f.rayTo[samples.stratum(j)]); }, rays);
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
        const VisibilitySamples samples(u);
        return stratifiedShare([&](int j) { return visible(patchAt(samples.fraction(j) * m_total)); }, rays);
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
