#include <radiosity/shooting_solver.h>

#include <radiosity/cluster_transfer.h>
#include <radiosity/patch_transfer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>

namespace rayrad::radiosity {

namespace {
/// Derived ΔI_max: this fraction of the scene's mean illuminance (measured trade-off, see
/// docs/validation.md).
constexpr double kDefaultStepFraction = 0.2;
}  // namespace

ShootingSolver::ShootingSolver(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                               const Visibility& vis, const scene::SolverOptions& solver,
                               const scene::ClusterOptions& clusters)
    : m_scene(scene), m_mesh(mesh), m_clustering(clustering), m_vis(vis), m_options(solver),
      m_clusterOptions(clusters) {
    m_reflectance.reserve(mesh.patches.size());
    for (const auto& p : mesh.patches) m_reflectance.push_back(scene.materials[p.material].reflectance);
}

void ShootingSolver::initialize(RadiositySolution& s) {
    size_t n = m_mesh.patches.size();
    s.indirect.assign(n, Rgb(0.0));
    s.unshot.assign(n, Rgb(0.0));
    double area = 0, meanDirect = 0, meanRho = 0;
    for (size_t i = 0; i < n; ++i) {
        const Patch& p = m_mesh.patches[i];
        const Rgb& rho = m_scene.materials[p.material].reflectance;
        s.unshot[i] = rho * s.directMean[i] / kPi;  // ΔL = ρ E / π
        area += p.area;
        meanDirect += luminance(s.directMean[i]) * p.area;
        meanRho += luminance(rho) * p.area;
    }
    if (area > 0) meanDirect /= area, meanRho /= area;
    // Mean illuminance with all bounces, estimated as Ē_dir / (1 − ρ̄).
    m_maxStep = m_clusterOptions.maxIlluminanceStep > 0
                    ? m_clusterOptions.maxIlluminanceStep
                    : kDefaultStepFraction * meanDirect / std::max(1e-6, 1.0 - meanRho);
    m_light.assign(m_clustering.clusters.size(), ClusterLight{});
    m_pending.assign(n, Rgb(0.0));
    for (size_t c = 0; c < m_light.size(); ++c) pull(c, s);
    s.shots = 0;
    s.initialUnshotFlux = unshotFlux(s);
    s.remainingUnshotFlux = s.initialUnshotFlux;
    s.converged = s.initialUnshotFlux <= 0;
    m_stats = {};
    m_shotSincePushPull = 0;
    m_powerAtPushPull = s.initialUnshotFlux / kPi;
}

double ShootingSolver::unshotFlux(const RadiositySolution& s) const {
    double flux = 0;
    for (size_t i = 0; i < m_mesh.patches.size(); ++i)
        flux += kPi * std::abs(luminance(s.unshot[i])) * m_mesh.patches[i].area;
    return flux;
}

double ShootingSolver::clusterPower(size_t c) const {
    const Cluster& C = m_clustering.clusters[c];
    const ClusterLight& l = m_light[c];
    // Candle power |ΔL|·A, counting what the pending I_C will add once pushed down.
    return std::abs(luminance(l.unshot + l.pendingReflected)) * C.area;
}

int ShootingSolver::radiusFor(size_t c) const {
    if (!m_clustering.enabled) return INT_MAX;
    const Cluster& C = m_clustering.clusters[c];
    double power = std::max(0.0, luminance(m_light[c].total)) * C.area;  // L_C A_C, cd
    double R = std::sqrt(power / m_maxStep);                             // m
    double rv = std::ceil(R / m_clustering.voxelSize);
    int maxDim = std::max({m_clustering.dims[0], m_clustering.dims[1], m_clustering.dims[2]});
    return static_cast<int>(std::clamp(rv, 1.0, static_cast<double>(maxDim + 1)));
}

void ShootingSolver::receive(size_t j, const Rgb& deltaE, RadiositySolution& s) {
    const Patch& p = m_mesh.patches[j];
    Rgb deltaL = m_reflectance[j] * deltaE / kPi;  // ΔL = ρ ΔE / π
    s.indirect[j] += deltaE;
    s.unshot[j] += deltaL;
    size_t c = m_clustering.clusterOf[j];
    double w = p.area / m_clustering.clusters[c].area;
    m_light[c].unshot += deltaL * w;  // pull up incrementally (eq. 1)
    m_light[c].total += deltaL * w;
}

void ShootingSolver::pull(size_t c, const RadiositySolution& s) {
    const Cluster& C = m_clustering.clusters[c];
    Rgb unshot(0.0), total(0.0);
    for (uint32_t j : C.patches) {
        double a = m_mesh.patches[j].area;
        unshot += s.unshot[j] * a;
        total += s.reflectedLuminance(m_scene, m_mesh, j) * a;
    }
    m_light[c].unshot = unshot / C.area;  // ΔL_C = Σ ΔL_i A_i / A_C   (eq. 1)
    m_light[c].total = total / C.area;    // L_C  = Σ L_i A_i / A_C
}

void ShootingSolver::addPending(const Cluster& source, size_t receiver, const Rgb& e) {
    const Cluster& D = m_clustering.clusters[receiver];
    thread_local std::vector<double> shape;
    receiverShape(m_mesh, source, D, m_clusterOptions.receiverDetail, shape);
    Rgb reflected(0.0);
    for (size_t k = 0; k < D.patches.size(); ++k) {
        uint32_t j = D.patches[k];
        Rgb ej = e * shape[k];
        m_pending[j] += ej;
        reflected += m_reflectance[j] * ej * m_mesh.patches[j].area;
    }
    m_light[receiver].pendingReflected += reflected / (kPi * D.area);
}

void ShootingSolver::pushPull(size_t c, RadiositySolution& s) {
    ClusterLight& l = m_light[c];
    {
        // Push down (eq. 2): L_i += I ρ_i/π, ΔL_i += I ρ_i/π, I = 0.
        for (uint32_t j : m_clustering.clusters[c].patches)
            if (m_pending[j] != Rgb(0.0)) {
                receive(j, m_pending[j], s);
                m_pending[j] = Rgb(0.0);
            }
        l.pendingReflected = Rgb(0.0);
    }
    pull(c, s);  // re-sync exactly, so incremental sums never drift
}

void ShootingSolver::pushPullAll(RadiositySolution& s) {
    tbb::parallel_for(size_t(0), m_light.size(), [&](size_t c) { pushPull(c, s); });
    ++m_stats.pushPulls;
    m_shotSincePushPull = 0;
    m_powerAtPushPull = 0;
    for (size_t c = 0; c < m_light.size(); ++c) m_powerAtPushPull += clusterPower(c);
}

bool ShootingSolver::coplanar(const Cluster& a, const Cluster& b) const {
    if (!a.planar || !b.planar || glm::dot(a.normal, b.normal) < 1 - 1e-12) return false;
    double scale = 1e-9 * (1 + a.diameter + b.diameter);
    return std::abs(glm::dot(b.centroid - a.centroid, a.normal)) < scale;
}

void ShootingSolver::shootPatches(const Cluster& source, const std::vector<Rgb>& amount, size_t receiver,
                                  RadiositySolution& s) {
    const Cluster& D = m_clustering.clusters[receiver];
    for (uint32_t j : D.patches) {
        const Patch& rec = m_mesh.patches[j];
        Rgb deltaE(0.0);
        for (size_t k = 0; k < source.patches.size(); ++k) {
            uint32_t i = source.patches[k];
            if (i == j || amount[k] == Rgb(0.0)) continue;
            const Patch& src = m_mesh.patches[i];
            Vec3 d = src.centroid - rec.centroid;  // both must face each other
            if (glm::dot(rec.normal, d) <= 0 || glm::dot(src.normal, d) >= 0) continue;
            double f = visiblePatchFormFactor(m_mesh, src, rec.centroid, rec.normal, m_options.analyticDistance, m_vis);
            deltaE += amount[k] * (kPi * f);  // ΔE = π ΔL F
        }
        if (deltaE != Rgb(0.0)) receive(j, deltaE, s);
    }
}

void ShootingSolver::shootCluster(size_t c, RadiositySolution& s, int radius) {
    const Cluster& C = m_clustering.clusters[c];
    ClusterLight& light = m_light[c];
    int r = radius >= 0 ? radius : radiusFor(c);
    const size_t n = m_clustering.clusters.size();
    std::vector<char> corrected(n, 0);
    const bool correcting = m_clustering.enabled && m_clusterOptions.energyCorrection;

    if (correcting && light.radius > 0 && r > light.radius) {
        // r_v grew: the ring old ≤ d < new switches from cluster→cluster to patch→patch.
        std::vector<Rgb> total(C.patches.size());
        for (size_t k = 0; k < C.patches.size(); ++k) total[k] = s.reflectedLuminance(m_scene, m_mesh, C.patches[k]);
        std::vector<size_t> ring;
        for (size_t d = 0; d < n; ++d) {
            int dist = m_clustering.voxelDistance(C, m_clustering.clusters[d]);
            if (d != c && dist >= light.radius && dist < r && !coplanar(C, m_clustering.clusters[d])) ring.push_back(d);
        }
        tbb::parallel_for(size_t(0), ring.size(), [&](size_t k) { correct(c, ring[k], total, s); });
        for (size_t d : ring) corrected[d] = 1;
        m_stats.corrections += static_cast<int64_t>(ring.size());
    }
    if (correcting) r = std::max(r, light.radius);  // r_v never shrinks: each receiver switches once

    // The shooter's unshot light leaves now; it may receive some of it back (intra-cluster).
    Rgb deltaLC = light.unshot;
    std::vector<Rgb> unshot(C.patches.size());
    for (size_t k = 0; k < C.patches.size(); ++k) {
        unshot[k] = s.unshot[C.patches[k]];
        s.unshot[C.patches[k]] = Rgb(0.0);
    }
    light.unshot = Rgb(0.0);

    std::atomic<int64_t> clusterTransfers{0}, patchPairs{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 16), [&](const tbb::blocked_range<size_t>& range) {
        int64_t cc = 0, pp = 0;
        for (size_t d = range.begin(); d != range.end(); ++d) {
            if (corrected[d]) continue;
            const Cluster& D = m_clustering.clusters[d];
            if (d == c ? C.planar : coplanar(C, D)) continue;  // coplanar surfaces exchange no light
            if (d != c && m_clustering.voxelDistance(C, D) >= r) {
                double t = clusterTransfer(m_mesh, C, D, m_vis, m_options.analyticDistance);
                if (t > 0) addPending(C, d, deltaLC * t);  // I_D += ΔL_C π F V
                ++cc;
            } else {
                shootPatches(C, unshot, d, s);
                pp += static_cast<int64_t>(C.patches.size() * D.patches.size());
            }
        }
        clusterTransfers += cc;
        patchPairs += pp;
    });
    m_stats.clusterTransfers += clusterTransfers;
    m_stats.patchPairs += patchPairs;
    light.radius = r;
}

bool ShootingSolver::step(RadiositySolution& s) {
    if (s.converged) return false;
    if (m_options.maxShots > 0 && s.shots >= m_options.maxShots) return false;
    size_t best = 0;
    double bestPower = -1, total = 0;
    for (size_t c = 0; c < m_light.size(); ++c) {
        double power = clusterPower(c);
        total += power;
        if (power > bestPower) bestPower = power, best = c;
    }
    s.remainingUnshotFlux = kPi * total;
    if (s.remainingUnshotFlux <= m_options.stopUnshot * s.initialUnshotFlux || bestPower <= 0) {
        s.converged = true;
        return false;
    }
    pushPull(best, s);  // the shooter's ΔL_C must match its patches' ΔL_i
    m_shotSincePushPull += clusterPower(best);
    shootCluster(best, s);
    ++s.shots;
    return true;
}

void ShootingSolver::solve(RadiositySolution& s, const std::function<void(const RadiositySolution&)>& onPushPull,
                           const std::function<void(const RadiositySolution&)>& onProgress) {
    auto start = std::chrono::steady_clock::now();
    auto lastReport = start;
    double paused = 0;  // seconds spent in callbacks, not counted as solve time
    while (step(s)) {
        if (m_shotSincePushPull > m_clusterOptions.pushPullFraction * m_powerAtPushPull) {
            pushPullAll(s);
            if (onPushPull) {
                auto t0 = std::chrono::steady_clock::now();
                s.seconds = std::chrono::duration<double>(t0 - start).count() - paused;
                onPushPull(s);
                paused += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            }
        }
        auto now = std::chrono::steady_clock::now();
        if (onProgress && now - lastReport > std::chrono::milliseconds(250)) {
            lastReport = now;
            onProgress(s);
        }
    }
    pushPullAll(s);
    s.remainingUnshotFlux = unshotFlux(s);
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - paused;
    if (onPushPull) onPushPull(s);
    if (onProgress) onProgress(s);
}

EnergyBalance energyBalance(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& s,
                            double emittedFlux) {
    EnergyBalance b;
    b.emitted = emittedFlux;
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        const Rgb& rho = scene.materials[p.material].reflectance;
        Rgb e = s.directMean[i] + (s.indirect.empty() ? Rgb(0.0) : s.indirect[i]);
        b.absorbed += luminance((Rgb(1.0) - rho) * e) * p.area;
        if (!s.unshot.empty()) b.unshot += kPi * luminance(s.unshot[i]) * p.area;
    }
    return b;
}

}  // namespace rayrad::radiosity
