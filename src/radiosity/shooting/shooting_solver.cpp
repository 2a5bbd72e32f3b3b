#include <radiosity/mesh/patch_reflectance.h>
#include <radiosity/shooting/shooting_solver.h>

#include <radiosity/shooting/shooting_core.h>
#include <radiosity/mesh/small_meshes.h>

#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>

namespace rayrad::radiosity {

bool isGreyScene(const scene::Scene& scene, const PatchMesh& mesh) {
    auto grey = [](const Rgb& c) { return c.r == c.g && c.g == c.b; };
    for (const auto& m : scene.materials)
        if (!grey(m.reflectance) || !grey(m.emission) || !grey(m.specular)) return false;
    for (const auto& rho : mesh.texturedReflectance)  // a grey multiplier of a coloured texture
        if (!grey(Rgb(rho))) return false;
    for (const auto& l : scene.lights)
        if (!grey(l.intensity)) return false;
    return true;
}

ShootingSolver::ShootingSolver(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                               const Visibility& vis)
    : m_singleChannel(scene.shooting.oneChannelWhenGrey && isGreyScene(scene, mesh)),
      m_oneThread(tooSmallToShare(mesh)) {
    if (m_singleChannel)
        m_core = std::make_unique<ShootingCore<double>>(scene, mesh, clustering, vis);
    else
        m_core = std::make_unique<ShootingCore<Rgb>>(scene, mesh, clustering, vis);
}

ShootingSolver::~ShootingSolver() = default;

void ShootingSolver::initialize(RadiositySolution& s) {
    m_core->initialize(s);
}
bool ShootingSolver::step(RadiositySolution& s) {
    return m_core->step(s, /*sync=*/true);
}
void ShootingSolver::pushPullAll(RadiositySolution& s) {
    m_core->pushPullAll();
    m_core->sync(s);
}

void ShootingSolver::shootCluster(size_t c, RadiositySolution& s, int radius) {
    m_core->shootCluster(c, radius);
    m_core->sync(s);
}

double ShootingSolver::maxIlluminanceStep() const {
    return m_core->maxIlluminanceStep();
}
std::vector<ClusterLight> ShootingSolver::clusterLight() const {
    return m_core->clusterLight();
}
const ShootingStatistics& ShootingSolver::statistics() const {
    return m_core->statistics();
}

double ShootingSolver::unshotFlux() const {
    return m_core->unshotFlux();
}

void ShootingSolver::solve(RadiositySolution& s, const PushPullHook& onPushPull,
                           const std::function<void(const RadiositySolution&)>& onProgress) {
    auto start = std::chrono::steady_clock::now();
    auto lastReport = start;
    double paused = 0;  // seconds spent in callbacks, not counted as solve time
    auto report = [&](bool last) {
        if (!onPushPull.call) return;
        auto t0 = std::chrono::steady_clock::now();
        s.seconds = std::chrono::duration<double>(t0 - start).count() - paused;
        if (!onPushPull.wants || onPushPull.wants(s)) {
            if (!last) m_core->sync(s);
            onPushPull.call(s);
            if (!last) std::vector<Rgb>().swap(s.indirect);  // the solver's own copy goes on
        }
        paused += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    };
    auto shoot = [&] {
        while (m_core->step(s, /*sync=*/false)) {
            if (m_core->pushPullDue()) {
                m_core->pushPullAll();
                report(false);
            }
            auto now = std::chrono::steady_clock::now();
            if (onProgress && now - lastReport > std::chrono::milliseconds(250)) {
                lastReport = now;
                onProgress(s);
            }
        }
        m_core->pushPullAll();
        m_core->finish(s);
    };
    if (m_oneThread)
        tbb::task_arena(1).execute(shoot);
    else
        shoot();
    s.remainingUnshotFlux = m_core->unshotFlux();  // kept by finish()
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - paused;
    report(true);
    if (onProgress) onProgress(s);
}

}  // namespace rayrad::radiosity
