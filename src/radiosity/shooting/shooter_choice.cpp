// Which cluster shoots next, and when the solve stops (see shooting_solver.h): the
// residual, the shooter with the most to ship (with overshooting, its ambient share
// too), and the stall and time limits.
#include <radiosity/shooting/shooting_core.h>

#include <core/check.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rayrad::radiosity {

namespace {
/// Shots without a new low of the residual before the solve counts as stalled (or a
/// quarter of the clusters, if more).
constexpr int64_t kStallShots = 2000;
}  // namespace

template <class V>
double ShootingCore<V>::clusterPower(size_t c) const {
    // Candle power |ΔL|·A, counting what the pending I_C will add once pushed down.
    const Light& l = m_light[c];
    return std::abs(lum(l.unshot + l.pendingReflected)) * m_clustering.clusters[c].area;
}

template <class V>
double ShootingCore<V>::clusterResidual(size_t c) const {
    const Light& l = m_light[c];
    return (std::max(0.0, l.absUnshot) + std::abs(lum(l.pendingReflected))) * m_clustering.clusters[c].area;
}

template <class V>
V ShootingCore<V>::ambientIlluminance() const {
    // E_amb = π ΔΦ (1 − e) / (A (1 − ρ̄ (1 − e))): the unshot power lands on the fraction
    // 1 − e of the surfaces, is reflected by ρ̄ each bounce, spread over the area A.
    double stays = 1.0 - m_stats.escapeFraction;
    V bounce = V(1.0) - m_meanReflectance * stays;
    return m_area > 0 ? kPi * m_signedUnshot * stays / (m_area * bounce) : V(0.0);
}

template <class V>
bool ShootingCore<V>::progressing(double residual) {
    // The residual need not fall at every shot (overshooting ships light ahead, and
    // corrections take some back), but it must reach a new low within a window of
    // shots. If it does not, overshooting is switched off (its estimate is what can go
    // round in circles); if it still does not, the solve stops and says so.
    if (residual < m_bestResidual * (1 - 1e-9)) {
        m_bestResidual = residual;
        m_shotsSinceBest = 0;
    } else if (++m_shotsSinceBest > std::max<int64_t>(kStallShots, static_cast<int64_t>(m_light.size()) / 4)) {
        m_shotsSinceBest = 0;
        if (m_options.overshoot) {
            m_options.overshoot = false;
            m_stats.overshooting = false;
            m_stats.overshootStalled = true;
        } else {
            m_stats.stopReason = "stalled: the residual stopped falling";
            return false;
        }
    }
    if (m_options.maxSeconds > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count() > m_options.maxSeconds) {
        m_stats.stopReason = "radiosity.max_seconds reached";
        return false;
    }
    return true;
}

template <class V>
bool ShootingCore<V>::step(RadiositySolution& s, bool syncAfter) {
    CHECK(!m_finished);
    if (s.converged) return false;
    if (m_options.maxShots > 0 && s.shots >= m_options.maxShots) {
        m_stats.stopReason = "radiosity.max_shots reached";
        return false;
    }
    // The residual is Σ |ΔL_C| A_C; with overshooting the shooter is the cluster that
    // would ship the most, |ΔL_C + ρ_C E_amb / π| A_C (a cluster that already shipped its
    // future light holds minus that and has nothing to ship).
    double total = 0;
    m_signedUnshot = V(0.0);
    for (size_t c = 0; c < m_light.size(); ++c) {
        total += clusterResidual(c);
        m_signedUnshot += (m_light[c].unshot + m_light[c].pendingReflected) * m_clustering.clusters[c].area;
    }
    const V ambient = m_options.overshoot ? ambientIlluminance() : V(0.0);
    size_t best = 0;
    double bestPower = -1;
    for (size_t c = 0; c < m_light.size(); ++c) {
        const Cluster& C = m_clustering.clusters[c];
        const Light& l = m_light[c];
        // The overshoot only of the lit members, as shootCluster() ships it: counting the
        // unlit ones picked a dark cluster (the underside of a sofa) whose shots ship
        // nothing, for ever.
        double power = std::abs(lum(l.unshot + l.pendingReflected + l.litReflectance * ambient / kPi)) * C.area;
        if (power > bestPower) bestPower = power, best = c;
    }
    s.remainingUnshotFlux = kPi * total;
    if (s.remainingUnshotFlux <= m_options.stopUnshot * s.unshotReference() || bestPower <= 0) {
        s.converged = true;
        return false;
    }
    if (!progressing(total)) return false;
    pushPull(best);  // the shooter's ΔL_C must match its patches' ΔL_i
    m_shotSincePushPull += clusterPower(best);
    shootCluster(best, -1);
    ++s.shots;
    if (syncAfter) sync(s);
    return true;
}

template double ShootingCore<double>::clusterPower(size_t) const;
template double ShootingCore<Rgb>::clusterPower(size_t) const;
template double ShootingCore<double>::clusterResidual(size_t) const;
template double ShootingCore<Rgb>::clusterResidual(size_t) const;
template double ShootingCore<double>::ambientIlluminance() const;
template Rgb ShootingCore<Rgb>::ambientIlluminance() const;
template bool ShootingCore<double>::progressing(double);
template bool ShootingCore<Rgb>::progressing(double);
template bool ShootingCore<double>::step(RadiositySolution&, bool);
template bool ShootingCore<Rgb>::step(RadiositySolution&, bool);

}  // namespace rayrad::radiosity
