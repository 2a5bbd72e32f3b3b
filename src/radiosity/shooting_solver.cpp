#include <radiosity/shooting_solver.h>

#include <radiosity/patch_transfer.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cmath>

namespace rayrad::radiosity {

ShootingSolver::ShootingSolver(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                               const scene::SolverOptions& options)
    : m_scene(scene), m_mesh(mesh), m_vis(vis), m_options(options) {}

void ShootingSolver::initialize(RadiositySolution& s) const {
    size_t n = m_mesh.patches.size();
    s.indirect.assign(n, Rgb(0.0));
    s.unshot.assign(n, Rgb(0.0));
    for (size_t i = 0; i < n; ++i) {
        const Rgb& rho = m_scene.materials[m_mesh.patches[i].material].reflectance;
        s.unshot[i] = rho * s.directMean[i] / kPi;  // ΔL = ρ E / π
    }
    s.shots = 0;
    s.initialUnshotFlux = unshotFlux(s);
    s.remainingUnshotFlux = s.initialUnshotFlux;
    s.converged = s.initialUnshotFlux <= 0;
}

double ShootingSolver::unshotFlux(const RadiositySolution& s) const {
    double flux = 0;
    for (size_t i = 0; i < m_mesh.patches.size(); ++i)
        flux += kPi * std::abs(luminance(s.unshot[i])) * m_mesh.patches[i].area;
    return flux;
}

bool ShootingSolver::step(RadiositySolution& s) const {
    if (s.converged) return false;
    if (m_options.maxShots > 0 && s.shots >= m_options.maxShots) return false;
    size_t best = 0;
    double bestPower = -1;
    double total = 0;
    for (size_t i = 0; i < m_mesh.patches.size(); ++i) {
        double power = std::abs(luminance(s.unshot[i])) * m_mesh.patches[i].area;  // candle power |ΔL|·A
        total += power;
        if (power > bestPower) bestPower = power, best = i;
    }
    s.remainingUnshotFlux = kPi * total;
    if (s.remainingUnshotFlux <= m_options.stopUnshot * s.initialUnshotFlux || bestPower <= 0) {
        s.converged = true;
        return false;
    }
    shoot(best, s);
    ++s.shots;
    return true;
}

void ShootingSolver::shoot(size_t source, RadiositySolution& s) const {
    const Patch& src = m_mesh.patches[source];
    const Rgb deltaL = s.unshot[source];
    s.unshot[source] = Rgb(0.0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, m_mesh.patches.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            if (i == source) continue;
            const Patch& rec = m_mesh.patches[i];
            // Quick rejection: both must face each other (centroid to centroid).
            Vec3 d = src.centroid - rec.centroid;
            if (glm::dot(rec.normal, d) <= 0 || glm::dot(src.normal, d) >= 0) continue;
            double f = visiblePatchFormFactor(m_mesh, src, rec.centroid, rec.normal, m_options.analyticDistance, m_vis);
            if (f <= 0) continue;
            Rgb deltaE = deltaL * (kPi * f);  // ΔE = π ΔL F
            s.indirect[i] += deltaE;
            s.unshot[i] += m_scene.materials[rec.material].reflectance * deltaE / kPi;
        }
    });
}

void ShootingSolver::solve(RadiositySolution& s, const std::function<void(const RadiositySolution&)>& onProgress) const {
    auto start = std::chrono::steady_clock::now();
    auto lastReport = start;
    while (step(s)) {
        auto now = std::chrono::steady_clock::now();
        if (onProgress && now - lastReport > std::chrono::milliseconds(250)) {
            lastReport = now;
            onProgress(s);
        }
    }
    s.remainingUnshotFlux = unshotFlux(s);
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
