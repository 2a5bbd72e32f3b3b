#include <core/check.h>
#include <radiosity/mesh/patch_reflectance.h>
#include <radiosity/shooting/shooting_core.h>

#include <radiosity/clusters/member_tree.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/form_factors/patch_transfer.h>
#include <radiosity/shooting/cluster_transfer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace rayrad::radiosity {

namespace {
/// Receivers a task of the delivery takes at least.
constexpr size_t kDeliverGrain = 64;
/// Receiving clusters a task of a shot's cluster transfers takes at least.
constexpr size_t kTransferGrain = 16;
}  // namespace

namespace {
/// Derived ΔI_max: this fraction of the scene's mean illuminance (measured trade-off, see
/// docs/validation.md).
constexpr double kDefaultStepFraction = 0.2;
/// Members per group (see member_tree.h).
constexpr size_t kGroupSize = 8;
}  // namespace

template <class V>
ShootingCore<V>::ShootingCore(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                              const Visibility& vis)
    : m_scene(scene),
      m_mesh(mesh),
      m_clustering(clustering),
      m_vis(vis),
      m_options(scene.shooting),
      m_analyticDistance(scene.formFactors.analyticDistance),
      m_mirrorImages(scene.mirrorImages.mirrors == scene::MirrorImageOptions::Mode::Image),
      m_clusterOptions(scene.clusters) {
    m_reflectance.reserve(mesh.patches.size());
    m_patchArea.reserve(mesh.patches.size());
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        m_reflectance.push_back(fromRgb<V>(patchReflectance(scene, mesh, i)));
        m_patchArea.push_back(p.area);
        m_meanReflectance += m_reflectance.back() * p.area;
        m_area += p.area;
    }
    if (m_area > 0) m_meanReflectance = m_meanReflectance / m_area;
    m_shotE.assign(mesh.patches.size(), V(0.0));
    m_shotPending.assign(mesh.patches.size(), V(0.0));
    m_reached.assign(clustering.clusters.size(), 0);
    m_trees.reserve(clustering.clusters.size());
    for (const Cluster& C : clustering.clusters) m_trees.push_back(memberTree(mesh, C, kGroupSize));
    m_regions = voxelRegions(clustering);
    if (clustering.enabled) m_touching = touchingClusters(mesh, clustering, vis, 1e-6 * scene.diagonal());
    m_sources.push_back({&vis, V(1.0), nullptr, {}, {}});
    m_mirrorViews = mirrorViewsFor(scene, vis, &m_mirrorChainsTruncated);
    if (m_mirrorImages)
        for (const auto& m : scene.mirrors) m_mirrorBacks.emplace_back(m.polygon.rbegin(), m.polygon.rend());
    for (const auto& view : m_mirrorViews) {
        // A cluster whose members all face away from the chain's ends takes no part.
        m_sources.push_back({view->path.get(), fromRgb<V>(view->image.weight), &view->image,
                             clustersFacing(scene.mirrors[view->image.chain.front()], mesh, clustering),
                             clustersFacing(scene.mirrors[view->image.chain.back()], mesh, clustering)});
    }
}

template <class V>
void ShootingCore<V>::initialize(RadiositySolution& s) {
    const size_t n = m_mesh.patches.size();
    m_direct.resize(n);
    m_indirect.assign(n, V(0.0));
    m_unshot.resize(n);
    m_pending.assign(n, V(0.0));
    double meanDirect = 0;
    for (size_t i = 0; i < n; ++i) {
        m_direct[i] = fromRgb<V>(s.directMean[i]);
        m_unshot[i] = m_reflectance[i] * m_direct[i] / kPi;  // ΔL = ρ E / π
        meanDirect += lum(m_direct[i]) * m_patchArea[i];
    }
    if (m_area > 0) meanDirect /= m_area;
    // Mean illuminance with all bounces, estimated as Ē_dir / (1 − ρ̄).
    m_maxStep = m_clusterOptions.maxIlluminanceStep > 0
                    ? m_clusterOptions.maxIlluminanceStep
                    : kDefaultStepFraction * meanDirect / std::max(1e-6, 1.0 - lum(m_meanReflectance));
    // Is the scene closed for the light that is in it? Rays leave from the patches in
    // proportion to their first reflected flux ρ E A.
    std::vector<double> firstFlux(n);
    for (size_t i = 0; i < n; ++i) firstFlux[i] = lum(m_unshot[i]) * m_patchArea[i];
    m_stats.escapeFraction = escapeFraction(m_mesh, m_vis, 4 * m_scene.diagonal() + 1.0, firstFlux);
    // With mirrors, every path through them must be modelled (complete chains) for the
    // light shot to be accounted: delivered / Π Ks summed over images.
    std::string conservationOff = !m_options.conserveEnergy                         ? "radiosity.conserve_energy"
                                  : m_stats.escapeFraction >= kClosedEscapeFraction ? "open scene"
                                  : m_scene.mirrors.empty()                         ? ""
                                  : !m_mirrorImages                                 ? "mirrors ignored"
                                  : m_mirrorChainsTruncated
                                      ? "mirror chains cut by mirror_depth, mirror_min_weight or mirror_min_share"
                                      : "";
    m_conserve = conservationOff.empty();
    m_light.assign(m_clustering.clusters.size(), Light{});
    for (size_t c = 0; c < m_light.size(); ++c) pull(c);
    s.shots = 0;
    s.initialUnshotFlux = unshotFlux();
    s.remainingUnshotFlux = s.initialUnshotFlux;
    s.converged = s.initialUnshotFlux <= 0;
    const double escape = m_stats.escapeFraction;
    m_stats = {};
    m_stats.escapeFraction = escape;
    m_stats.conserving = m_conserve;
    m_stats.conservationOff = conservationOff;
    m_stats.overshooting = m_options.overshoot;
    m_shotSincePushPull = 0;
    m_powerAtPushPull = s.initialUnshotFlux / kPi;
    m_bestResidual = std::numeric_limits<double>::infinity();
    m_shotsSinceBest = 0;
    m_start = std::chrono::steady_clock::now();
}

template <class V>
void ShootingCore<V>::sync(RadiositySolution& s) const {
    CHECK(!m_finished);
    const size_t n = m_mesh.patches.size();
    s.indirect.resize(n);
    for (size_t i = 0; i < n; ++i) s.indirect[i] = toRgb(m_indirect[i]);
    s.unshotNetFlux = unshotNetFlux();
    s.mirrorAbsorbedSecondary = m_stats.mirrorAbsorbed;
}

template <class V>
void ShootingCore<V>::finish(RadiositySolution& s) {
    auto release = [](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); };
    // What only the shots read goes before the solution's array is allocated ...
    release(m_shotE), release(m_shotPending), release(m_pending), release(m_reflectance), release(m_direct);
    sync(s);
    m_finishedUnshotFlux = unshotFlux();
    m_finished = true;
    // ... and what sync() read, after.
    release(m_indirect), release(m_unshot), release(m_patchArea);
}

template <class V>
std::vector<ClusterLight> ShootingCore<V>::clusterLight() const {
    std::vector<ClusterLight> out;
    for (const auto& l : m_light) out.push_back({toRgb(l.unshot), toRgb(l.total), toRgb(l.pendingReflected), l.radius});
    return out;
}

template <class V>
double ShootingCore<V>::unshotFlux() const {
    if (m_finished) return m_finishedUnshotFlux;
    double flux = 0;
    for (size_t i = 0; i < m_mesh.patches.size(); ++i) flux += kPi * std::abs(lum(m_unshot[i])) * m_patchArea[i];
    return flux;
}

template <class V>
double ShootingCore<V>::unshotNetFlux() const {
    double flux = 0;
    for (size_t i = 0; i < m_mesh.patches.size(); ++i) flux += kPi * luminance(toRgb(m_unshot[i])) * m_patchArea[i];
    return flux;
}

template <class V>
int ShootingCore<V>::radiusFor(size_t c) const {
    if (!m_clustering.enabled) return INT_MAX;
    const Cluster& C = m_clustering.clusters[c];
    double power = std::max(0.0, lum(m_light[c].total)) * C.area;  // L_C A_C, cd
    double R = std::sqrt(power / m_maxStep);                       // m
    double rv = std::ceil(R / m_clustering.voxelSize);
    int maxDim = std::max({m_clustering.dims[0], m_clustering.dims[1], m_clustering.dims[2]});
    return static_cast<int>(std::clamp(rv, 1.0, static_cast<double>(maxDim + 1)));
}

template <class V>
void ShootingCore<V>::receive(size_t j, const V& deltaE) {
    V deltaL = m_reflectance[j] * deltaE / kPi;  // ΔL = ρ ΔE / π
    m_indirect[j] += deltaE;
    double before = std::abs(lum(m_unshot[j]));
    m_unshot[j] += deltaL;
    size_t c = m_clustering.clusterOf[j];
    double w = m_patchArea[j] / m_clustering.clusters[c].area;
    m_light[c].unshot += deltaL * w;  // pull up incrementally (eq. 1)
    m_light[c].total += deltaL * w;
    m_light[c].absUnshot += (std::abs(lum(m_unshot[j])) - before) * w;
}

template <class V>
void ShootingCore<V>::pull(size_t c) {
    const Cluster& C = m_clustering.clusters[c];
    V unshot(0.0), total(0.0), litReflectance(0.0);
    double absUnshot = 0;
    for (uint32_t j : C.patches) {
        double a = m_patchArea[j];
        unshot += m_unshot[j] * a;
        total += reflected(j) * a;
        absUnshot += std::abs(lum(m_unshot[j])) * a;
        if (isLit(j)) litReflectance += m_reflectance[j] * a;
    }
    m_light[c].litReflectance = litReflectance / C.area;
    m_light[c].unshot = unshot / C.area;  // ΔL_C = Σ ΔL_i A_i / A_C   (eq. 1)
    m_light[c].total = total / C.area;    // L_C  = Σ L_i A_i / A_C
    m_light[c].absUnshot = absUnshot / C.area;
}

template <class V>
typename ShootingCore<V>::Delivery ShootingCore<V>::addPending(const Cluster& source, size_t receiver, const V& e,
                                                               const std::vector<double>* visible) {
    const Cluster& D = m_clustering.clusters[receiver];
    thread_local std::vector<double> shape;
    receiverShape(m_mesh, source, D, m_clusterOptions.receiverDetail, shape);
    if (visible)
        for (size_t k = 0; k < shape.size(); ++k) shape[k] *= (*visible)[k];
    Delivery out;
    m_reached[receiver] |= kReachedPending;
    for (size_t k = 0; k < D.patches.size(); ++k) {
        uint32_t j = D.patches[k];
        m_shotPending[j] += e * shape[k];
        out.flux += e * shape[k] * m_patchArea[j];
    }
    out.magnitude = std::abs(lum(out.flux));  // every member's share has the sign of e (shape ≥ 0)
    return out;
}

template <class V>
void ShootingCore<V>::pushPull(size_t c) {
    // Push down (eq. 2): L_i += I ρ_i/π, ΔL_i += I ρ_i/π, I = 0.
    for (uint32_t j : m_clustering.clusters[c].patches)
        if (m_pending[j] != V(0.0)) {
            receive(j, m_pending[j]);
            m_pending[j] = V(0.0);
        }
    m_light[c].pendingReflected = V(0.0);
    pull(c);  // re-sync exactly, so incremental sums never drift
}

template <class V>
void ShootingCore<V>::pushPullAll() {
    CHECK(!m_finished);
    tbb::parallel_for(size_t(0), m_light.size(), [&](size_t c) { pushPull(c); });
    ++m_stats.pushPulls;
    m_shotSincePushPull = 0;
    m_powerAtPushPull = 0;
    for (size_t c = 0; c < m_light.size(); ++c) m_powerAtPushPull += clusterResidual(c);
}

template <class V>
bool ShootingCore<V>::coplanar(const Cluster& a, const Cluster& b) const {
    if (!a.planar || !b.planar || glm::dot(a.normal, b.normal) < 1 - 1e-12) return false;
    double scale = 1e-9 * (1 + a.diameter + b.diameter);
    return std::abs(glm::dot(b.centroid - a.centroid, a.normal)) < scale;
}

template <class V>
std::vector<V> ShootingCore<V>::overshootOf(const Cluster& C) const {
    // With overshooting each member also ships what it will receive later, ρ_i E_amb / π,
    // and keeps minus that as unshot light. A patch that has received no light so far
    // (the underside of a box on the floor) is taken to receive none later: it gets no
    // overshoot it could not ship.
    const V ambient = m_options.overshoot ? ambientIlluminance() : V(0.0);
    std::vector<V> overshoot(C.patches.size(), V(0.0));
    for (size_t k = 0; k < C.patches.size(); ++k) {
        uint32_t i = C.patches[k];
        if (isLit(i)) overshoot[k] = m_reflectance[i] * ambient / kPi;
    }
    return overshoot;
}

template <class V>
void ShootingCore<V>::releaseUnshot(Shot& shot) {
    const Cluster& C = m_clustering.clusters[shot.c];
    Light& light = m_light[shot.c];
    shot.unshot.resize(C.patches.size());
    shot.unshotPower.resize(C.patches.size());
    V deltaLC(0.0), keptLC(0.0);
    for (size_t k = 0; k < C.patches.size(); ++k) {
        uint32_t i = C.patches[k];
        shot.unshot[k] = m_unshot[i] + shot.overshoot[k];
        m_unshot[i] = -shot.overshoot[k];
        double a = m_patchArea[i];
        shot.unshotPower[k] = lum(shot.unshot[k]) * a;
        shot.shotFlux += kPi * shot.unshotPower[k];
        deltaLC += shot.unshot[k] * a;
        keptLC -= shot.overshoot[k] * a;
    }
    shot.deltaLC = deltaLC / C.area;
    light.unshot = keptLC / C.area;
    light.absUnshot = std::abs(lum(keptLC)) / C.area;  // every member keeps −ρ_i E_amb/π: one sign
}

template <class V>
void ShootingCore<V>::prepareSources(Shot& shot, const ClusterSamples& samples) const {
    const size_t sources = m_sources.size();
    shot.localSamples.resize(sources);
    shot.regionOpen.resize(sources);
    for (size_t si = 0; si < sources; ++si) {
        if (!shot.shooters[si]) continue;
        const Source& s = m_sources[si];
        const Cluster& Cs = shot.shooters[si]->cluster();
        shot.localSamples[si] = shot.shooters[si]->local(samples);
        if (!s.image) continue;
        shot.regionOpen[si].resize(m_regions.regions.size());
        for (size_t k = 0; k < shot.regionOpen[si].size(); ++k)
            shot.regionOpen[si][k] = s.image->mayPass(Cs.centroid, 0.5 * Cs.diameter, m_regions.regions[k].centre,
                                                      m_regions.regions[k].radius);
    }
}

template <class V>
void ShootingCore<V>::shootClusterToCluster(Shot& shot) {
    // Every source's transfers to receiver d are made by one task, source by source, so
    // each receiver's deliveries add up in the same order at any thread count; the
    // sources share each pass's parallel loop (a loop per source would fork and join once
    // per source and shot).
    const size_t c = shot.c, n = m_clustering.clusters.size(), sources = m_sources.size();
    const Cluster& C = m_clustering.clusters[c];
    shot.isNear.assign(sources * n, 0);
    shot.nearAny.assign(n, 0);
    std::vector<double> luminance(C.patches.size());
    for (size_t k = 0; k < C.patches.size(); ++k) luminance[k] = lum(shot.unshot[k]);
    const SourceLight light = sourceLight(m_mesh, C, m_trees[c], luminance);  // how ΔL is spread over C
    std::atomic<int64_t> clusterTransfers{0}, splitTransfers{0}, imageTransfers{0}, imageLit{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kTransferGrain), [&](const tbb::blocked_range<size_t>& range) {
        int64_t cc = 0, split = 0, ccImage = 0, litImage = 0;
        for (size_t d = range.begin(); d != range.end(); ++d) {
            const Cluster& D = m_clustering.clusters[d];
            for (size_t si = 0; si < sources; ++si) {
                if (!shot.shooters[si] || shot.corrected[si][d]) continue;
                const Source& s = m_sources[si];
                const Shooter& from = *shot.shooters[si];
                const Cluster& Cs = from.cluster();
                bool self = d == c && !s.image;
                if (s.image && !shot.regionOpen[si][m_regions.regionOf[d]]) continue;
                if (self ? C.planar : coplanar(Cs, D)) continue;  // coplanar surfaces exchange no light
                if (!canReach(s, Cs, c, d)) continue;
                if (self || inNearField(s, Cs, c, d, shot.r)) {
                    shot.isNear[si * n + d] = 1, shot.nearAny[d] = 1;
                    continue;
                }
                SplitTransfer parts;
                double t =
                    clusterTransfer(from.mesh(), Cs, shot.localSamples[si], m_mesh, D, *s.vis, m_analyticDistance,
                                    m_clusterOptions.receiverDetail, &from.geometry, &light, &parts);
                bool carried = false;
                if (parts.partial) {  // a shadow's edge crosses D: each member's own V
                    thread_local std::vector<double> visible;
                    memberVisibility(from.mesh(), shot.localSamples[si], m_mesh, D, *s.vis, visible);
                    const Delivery got = addPending(Cs, d, shot.deltaLC * s.weight * parts.open, &visible);
                    shot.bookedAt[d].add(s, got), ++split;
                    carried = got.flux != V(0.0);  // every member's rays may have been blocked
                } else if (t > 0) {
                    // I_D += Ks ΔL_C π F V
                    shot.bookedAt[d].add(s, addPending(Cs, d, shot.deltaLC * s.weight * t)), carried = true;
                }
                ++cc;
                if (s.image) ++ccImage, litImage += carried;
            }
        }
        clusterTransfers += cc;
        splitTransfers += split;
        imageTransfers += ccImage;
        imageLit += litImage;
    });
    m_stats.clusterTransfers += clusterTransfers;
    m_stats.splitTransfers += splitTransfers;
    m_stats.imageTransfers += imageTransfers, m_stats.imageTransfersLit += imageLit;
}

template <class V>
void ShootingCore<V>::shootPatchToPatch(Shot& shot) {
    const size_t n = m_clustering.clusters.size(), sources = m_sources.size();
    std::vector<size_t> nearReceivers;
    std::vector<char> sendsNear(sources, 0);
    for (size_t d = 0; d < n; ++d) {
        if (!shot.nearAny[d]) continue;
        nearReceivers.push_back(d);
        for (size_t si = 0; si < sources; ++si) sendsNear[si] |= shot.isNear[si * n + d];
    }
    std::vector<std::optional<Emission>> shotLight(sources);
    for (size_t si = 0; si < sources; ++si)
        if (sendsNear[si]) shotLight[si].emplace(emission(*shot.shooters[si], shot.c, shot.unshot));
    std::atomic<int64_t> patchPairs{0};
    const tbb::blocked_range<size_t> nearRange(0, nearReceivers.size(), 4);
    tbb::parallel_for(nearRange, [&](const tbb::blocked_range<size_t>& range) {
        int64_t pp = 0;
        for (size_t k = range.begin(); k != range.end(); ++k) {
            const size_t d = nearReceivers[k];
            for (size_t si = 0; si < sources; ++si) {
                if (!shot.isNear[si * n + d]) continue;
                const Source& s = m_sources[si];
                shot.bookedAt[d].add(s, shootPatches(s, *shot.shooters[si], shot.c, *shotLight[si], d, m_shotE, pp));
            }
        }
        patchPairs += pp;
    });
    m_stats.patchPairs += patchPairs;
}

template <class V>
void ShootingCore<V>::shootCluster(size_t c, int radius) {
    CHECK(!m_finished);
    Light& light = m_light[c];
    const Cluster& C = m_clustering.clusters[c];
    const size_t n = m_clustering.clusters.size();
    Shot shot;
    shot.c = c;
    shot.r = radius >= 0 ? radius : radiusFor(c);
    shot.overshoot = overshootOf(C);
    // The shooter as each source shows it (an image: its mirrored copy), built once per
    // shot; none where nothing of c passes the source's chain.
    shot.shooters.resize(m_sources.size());
    for (size_t si = 0; si < m_sources.size(); ++si)
        if (!m_sources[si].image || m_sources[si].sends[c]) shot.shooters[si].emplace(shooter(m_sources[si], c));
    shot.corrected.assign(m_sources.size(), std::vector<char>(n, 0));
    const bool correcting = m_clustering.enabled && m_clusterOptions.energyCorrection;
    double redelivered = 0;  // lm (at the source) of earlier shots the corrections took away
    const bool throughMirrors = m_sources.size() > 1;
    AtSource delivered{throughMirrors};  // this shot's deliveries at the source
    if (correcting && light.radius > 0 && shot.r > light.radius)
        redelivered = correctRing(c, shot.r, shot.overshoot, shot.shooters, shot.corrected, delivered);
    if (correcting) shot.r = std::max(shot.r, light.radius);  // r_v never shrinks: each receiver switches once

    // The shooter's light leaves now; it may receive some of it back (intra-cluster).
    // Deliveries are collected first (patch→patch in m_shotE, cluster→cluster in
    // m_shotPending) so that a closed scene can scale them to the flux shot. Each
    // receiver's deliveries are booked at their source by its own task, sources in order,
    // and added up in receiver order after the passes (the same sums at any thread count).
    releaseUnshot(shot);
    prepareSources(shot, powerSamples(C, shot.unshotPower));
    shot.bookedAt.assign(n, AtSource{throughMirrors});
    shootClusterToCluster(shot);
    shootPatchToPatch(shot);
    for (const AtSource& booked : shot.bookedAt) delivered.add(booked);
    if (!m_mirrorBacks.empty()) {  // what goes into a mirror's back is absorbed there, not delivered
        double back = intoMirrorBacks(C, shot.unshotPower);
        shot.shotFlux -= back;
        m_stats.mirrorAbsorbed += back;
    }
    checkFinite(c, shot.shotFlux, redelivered, delivered);
    deliver(shot.shotFlux, redelivered, delivered);
    light.radius = shot.r;
}

template <class V>
void ShootingCore<V>::checkFinite(size_t c, double shotFlux, double redelivered, const AtSource& delivered) const {
    if (std::isfinite(shotFlux) && std::isfinite(redelivered) && std::isfinite(delivered.magnitude)) return;
    const Cluster& C = m_clustering.clusters[c];
    std::ostringstream s;
    s << "a shot from cluster " << c << " (" << C.patches.size() << " patches, centroid (" << C.centroid.x << ", "
      << C.centroid.y << ", " << C.centroid.z << "), area " << C.area << " m²) is not finite: flux shot " << shotFlux
      << " lm, redelivered " << redelivered << " lm, delivered " << delivered.magnitude << " lm";
    auto describe = [&](uint32_t i) {
        const Patch& p = m_mesh.patches[i];
        s << "patch " << i << " (" << m_scene.materials[p.material].name << ", centroid (" << p.centroid.x << ", "
          << p.centroid.y << ", " << p.centroid.z << "), area " << p.area << " m², normal (" << p.normal.x << ", "
          << p.normal.y << ", " << p.normal.z << "))";
    };
    for (uint32_t i : C.patches)
        if (!std::isfinite(lum(m_unshot[i])) || !std::isfinite(lum(m_indirect[i])) || !(m_patchArea[i] > 0)) {
            s << "; the shooter's ";
            describe(i);
            s << " holds unshot " << lum(m_unshot[i]) << ", indirect " << lum(m_indirect[i]);
            break;
        }
    for (uint32_t j = 0; j < m_shotE.size(); ++j)
        if (!std::isfinite(lum(m_shotE[j])) || !std::isfinite(lum(m_shotPending[j]))) {
            s << "; the first receiver not finite: ";
            describe(j);
            s << (std::isfinite(lum(m_shotE[j])) ? " (cluster→cluster)" : " (patch→patch)");
            break;
        }
    throw InternalError(s.str());
}

template <class V>
void ShootingCore<V>::deliver(double shotFlux, double redelivered, const AtSource& delivered) {
    std::vector<uint32_t> reached;  // the clusters with deliveries waiting, in index order
    for (size_t d = 0; d < m_reached.size(); ++d)
        if (m_reached[d]) reached.push_back(static_cast<uint32_t>(d));
    // Closed scene: Σ_j ΔE_j A_j must equal the flux shot (Σ_j F_ij = 1), plus what the
    // corrections took away to deliver again; through mirrors each delivery counts as it
    // left the shooter (÷ Π Ks: the mirrors absorbed the rest). The deficit δ is shared in
    // proportion to |ΔE_j| A_j: ΔE_j (1 + sgn(ΔE_j) δ / Σ|ΔE_k| A_k), which is a plain
    // rescale when every delivery has one sign and stays exact when an overshooting
    // cluster ships light of both signs.
    // Open scene: some of the flux shot escapes, so less may arrive (Σ_j F_ij < 1), but
    // never more — of either sign: an overshooting shooter may ship negative light. More
    // arrives where surfaces nearly coincide (a CAD exporter's walls and outer shell 0.3 mm
    // apart, pieces of the two in one plane): such a surplus is taken away the same way.
    // Not in a shot with corrections: what they took away is the earlier cluster→cluster
    // estimate, and the patch→patch one that replaces it may rightly be larger.
    double adjust = 0;  // δ / Σ|ΔE_k| A_k
    const double deficit = shotFlux + redelivered - delivered.net;
    const bool surplus = redelivered == 0 && (shotFlux > 0 ? deficit < 0 : deficit > 0);
    if (m_conserve || surplus) {
        if (delivered.magnitude > 0 && std::abs(deficit) <= kConservationBound * delivered.magnitude) {
            adjust = deficit / delivered.magnitude;
            m_stats.largestRescale = std::max(m_stats.largestRescale, std::abs(adjust));
            if (!m_conserve) ++m_stats.cappedShots;
        } else if (shotFlux != 0) {
            ++m_stats.unbalancedShots;
        }
    }
    auto adjusted = [adjust](const V& e) { return e * (1.0 + (lum(e) < 0 ? -adjust : adjust)); };
    // The mirrors absorb in proportion to what they pass on.
    const double loss = delivered.mirrorLoss;
    m_stats.mirrorAbsorbed += loss * (1.0 + (loss < 0 ? -adjust : adjust));
    // Chunks of receivers: a receiver's work is a few patches, and a task per receiver costs
    // more than it does in small scenes.
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, reached.size(), kDeliverGrain), [&](const tbb::blocked_range<size_t>& range) {
            for (size_t k = range.begin(); k != range.end(); ++k) {
                const size_t d = reached[k];
                const Cluster& D = m_clustering.clusters[d];
                V reflectedSum(0.0);
                // At 1.2 M patches this loop waits on memory: an array that holds nothing for D
                // (most receivers are reached cluster→cluster only) is not read.
                const bool patches = m_reached[d] & kReachedPatches, pending = m_reached[d] & kReachedPending;
                m_reached[d] = 0;
                for (uint32_t j : D.patches) {
                    if (patches && m_shotE[j] != V(0.0)) {
                        receive(j, adjusted(m_shotE[j]));
                        m_shotE[j] = V(0.0);
                    }
                    if (pending && m_shotPending[j] != V(0.0)) {  // I_D joins the pending light, pushed down later
                        V e = adjusted(m_shotPending[j]);
                        m_pending[j] += e;
                        reflectedSum += m_reflectance[j] * e * m_patchArea[j];
                        m_shotPending[j] = V(0.0);
                    }
                }
                m_light[d].pendingReflected += reflectedSum / (kPi * D.area);
            }
        });
}

template class ShootingCore<double>;
template class ShootingCore<Rgb>;

}  // namespace rayrad::radiosity
