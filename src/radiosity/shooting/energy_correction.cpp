// The energy-transfer correction (Myszkowski & Kunii, section 3.3).
#include <radiosity/shooting/cluster_transfer.h>
#include <radiosity/shooting/shooting_core.h>

#include <tbb/parallel_for.h>

namespace rayrad::radiosity {

/// When the shooter C's radius r_v grows, a receiver cluster D in the ring between the
/// old and the new radius switches from cluster→cluster to patch→patch. Then:
///  1. reconstruct the illuminance D received from C in earlier cluster→cluster shots:
///     C has shot (L_C − ΔL_C) in all (every shot ships the current ΔL_C), and the
///     transfer factor and the receiver shape are deterministic, so
///     I^r_j = (L_C − ΔL_C) · π F V · shape_j;
///  2. take it away from every patch of D: E_j −= I^r_j, ΔL_j −= ρ_j I^r_j / π (ΔL may go
///     negative: that is legitimate unshot energy and is shot later like any other);
///  3. shoot C's *total* luminance L_i of every member patch→patch to D's patches
///     (this includes the current ΔL_i, so D takes no part in this step's regular shot);
///     like the regular shot's, these deliveries wait in m_shotE for deliver();
///  4. push-pull D.
/// `totalOfSource.amount[k]` is what C's k-th member will have shipped after this shot:
/// L_i, plus its overshoot. Touches only D's state, so receivers can be corrected in
/// parallel. Returns the flux taken away in step 2 (it was delivered by earlier shots,
/// and a conserving shot must deliver it again: step 3 re-estimates it together with
/// this shot's share, and deliver() scales the two as one) and the flux step 3 delivers.
/// A mirror image of C (source s) is corrected the same way, with its own geometry,
/// its path visibility and its weight Π Ks.
template <class V>
typename ShootingCore<V>::Correction ShootingCore<V>::correct(const Source& s, const Shooter& from, size_t c, size_t d,
                                                              const ClusterSamples& shotSamples,
                                                              const SourceLight& shipped,
                                                              const Emission& totalOfSource) {
    const Cluster& C = from.cluster();
    const Cluster& D = m_clustering.clusters[d];
    pushPull(d);  // anything C sent earlier and still pending is now on D's patches
    V shotSoFar = m_light[c].total - m_light[c].unshot;
    Correction moved;
    SplitTransfer split;
    const double t = clusterTransfer(from.mesh(), C, shotSamples, m_mesh, D, *s.vis, m_analyticDistance,
                                     m_clusterOptions.receiverDetail, &from.geometry, &shipped, &split);
    V received = shotSoFar * s.weight * (split.partial ? split.open : t);
    if (received != V(0.0)) {
        std::vector<double> shape;
        receiverShape(m_mesh, C, D, m_clusterOptions.receiverDetail, shape);
        if (split.partial) {  // as the shots delivered it: each member's own V
            std::vector<double> visible;
            memberVisibility(from.mesh(), shotSamples, m_mesh, D, *s.vis, visible);
            for (size_t k = 0; k < shape.size(); ++k) shape[k] *= visible[k];
        }
        for (size_t k = 0; k < D.patches.size(); ++k) {
            uint32_t j = D.patches[k];
            receive(j, -(received * shape[k]));
            moved.removed += received * shape[k] * m_patchArea[j];
        }
    }
    int64_t terms = 0;
    moved.delivered = shootPatches(s, from, c, totalOfSource, d, m_shotE, terms);
    pull(d);
    return moved;
}

template <class V>
double ShootingCore<V>::correctRing(size_t c, int r, const std::vector<V>& overshoot,
                                    const std::vector<std::optional<Shooter>>& shooters,
                                    std::vector<std::vector<char>>& corrected, AtSource& delivered) {
    // The ring old ≤ d < new switches from cluster→cluster to patch→patch, for the real
    // shooter and for each of its mirror images.
    const Cluster& C = m_clustering.clusters[c];
    const int old = m_light[c].radius;
    std::vector<V> total(C.patches.size());           // what member i will have shipped after this shot
    std::vector<double> shotPower(C.patches.size());  // what earlier shots carried, ≈ (L_i − ΔL_i) A_i
    std::vector<double> shotLuminance(C.patches.size());
    for (size_t k = 0; k < C.patches.size(); ++k) {
        uint32_t i = C.patches[k];
        total[k] = reflected(i) + overshoot[k];
        shotLuminance[k] = lum(reflected(i) - m_unshot[i]);
        shotPower[k] = shotLuminance[k] * m_patchArea[i];
    }
    const ClusterSamples shotSamples = powerSamples(C, shotPower);
    // Earlier shots each sent their own ΔL_i; in all, L_i − ΔL_i: the transfer with that
    // spread is the sum of theirs.
    const SourceLight shipped = sourceLight(m_mesh, C, m_trees[c], shotLuminance);
    double redelivered = 0;
    for (size_t si = 0; si < m_sources.size(); ++si) {
        const Source& s = m_sources[si];
        if (!shooters[si]) continue;
        const Shooter& from = *shooters[si];
        const Cluster& Cs = from.cluster();
        const ClusterSamples localShotSamples = from.local(shotSamples);
        std::vector<size_t> ring;
        for (size_t d = 0; d < m_clustering.clusters.size(); ++d) {
            if (d == c && !s.image) continue;
            if (inNearField(s, Cs, c, d, r) && !inNearField(s, Cs, c, d, old) &&
                !coplanar(Cs, m_clustering.clusters[d]) && canReach(s, Cs, c, d))
                ring.push_back(d);
        }
        std::vector<Correction> moved(ring.size());
        if (!ring.empty()) {
            const Emission totalLight = emission(from, c, total);
            tbb::parallel_for(size_t(0), ring.size(), [&](size_t k) {
                moved[k] = correct(s, from, c, ring[k], localShotSamples, shipped, totalLight);
            });
        }
        for (const Correction& m : moved) {
            redelivered += lum(atSource(m.removed, s.weight));
            delivered.add(s, m.delivered);
            if (s.image) m_stats.mirrorAbsorbed -= lum(mirrorLoss(m.removed, s.weight));
        }
        for (size_t d : ring) corrected[si][d] = 1;
        m_stats.corrections += static_cast<int64_t>(ring.size());
    }
    return redelivered;
}

template ShootingCore<double>::Correction ShootingCore<double>::correct(const Source&, const Shooter&, size_t, size_t,
                                                                        const ClusterSamples&, const SourceLight&,
                                                                        const Emission&);
template ShootingCore<Rgb>::Correction ShootingCore<Rgb>::correct(const Source&, const Shooter&, size_t, size_t,
                                                                  const ClusterSamples&, const SourceLight&,
                                                                  const Emission&);

template double ShootingCore<double>::correctRing(size_t, int, const std::vector<double>&,
                                                  const std::vector<std::optional<Shooter>>&,
                                                  std::vector<std::vector<char>>&, AtSource&);
template double ShootingCore<Rgb>::correctRing(size_t, int, const std::vector<Rgb>&,
                                               const std::vector<std::optional<Shooter>>&,
                                               std::vector<std::vector<char>>&, AtSource&);

}  // namespace rayrad::radiosity
