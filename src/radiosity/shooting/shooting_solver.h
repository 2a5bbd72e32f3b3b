// The secondary pass: progressive shooting over the two-level hierarchy (clusters, patches).
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/shooting/shooting_statistics.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>
#include <scene/settings.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rayrad::radiosity {

class ShootingCoreBase;

/// Shooting (Cohen et al. 1988) over clusters and patches with the energy-transfer
/// correction of Myszkowski & Kunii. Each step picks the cluster with the largest unshot
/// power |Y(ΔL_C)|·A_C (pending I_C included), push-pulls it, and shoots ΔL to every
/// receiver cluster D:
///  - cluster→cluster where D's voxel is at Chebyshev distance ≥ r_v from the shooter's,
///    r_v = ceil(R / voxel), R = sqrt(Y(L_C) A_C / ΔI_max):  I_D += ΔL_C · π F V;
///  - patch→patch otherwise, and inside the shooter:  E_j += Σ_i ΔL_i π F(c_j → i) V.
/// When r_v grows, the receivers in the ring between the old and the new radius are
/// corrected (see energy_correction.cpp). Receivers are independent, so each shot runs
/// in parallel over receiver clusters and the result does not depend on thread count.
/// Without clusters every patch is its own cluster and every transfer patch→patch.
/// When every reflectance and every light is grey, one channel is solved instead of
/// three (shooting_core.h); the solution's RGB arrays are filled at the end of step(),
/// pushPullAll(), shootCluster() and solve() (initialize() leaves them to those).
class ShootingSolver {
  public:
    ShootingSolver(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                   const Visibility& vis);
    ~ShootingSolver();

    /// Starts from the direct pass: ΔL_i = ρ_i Ē_direct,i / π, E_indirect = 0.
    void initialize(RadiositySolution& solution);
    /// One shot; false (and nothing done) once converged or out of shots.
    bool step(RadiositySolution& solution);
    /// What solve() calls after every global push-pull (the solution is consistent then).
    /// `wants` sees the solution's figures (shots, unshot flux, converged) and says
    /// whether this push-pull needs the per-patch array; only then is `indirect` filled
    /// for `call` (with the unshot net flux), and released after it: while it shoots, the
    /// solver holds the light in its own arrays, and a second copy would add 24 bytes per
    /// patch.
    /// No `wants`: every push-pull.
    struct PushPullHook {
        std::function<bool(const RadiositySolution&)> wants;
        std::function<void(const RadiositySolution&)> call;
    };
    /// Iterates to the stopping rule and fills the solution's arrays at the end (the
    /// solver's own are freed then: it cannot shoot after solve()). `onPushPull` as
    /// above, the last time after the arrays are filled; `onProgress` now and then, with
    /// the solution's figures only.
    void solve(RadiositySolution& solution, const PushPullHook& onPushPull = {},
               const std::function<void(const RadiositySolution&)>& onProgress = {});
    /// Pushes every pending I_C down to the patches and pulls ΔL_C, L_C up.
    void pushPullAll(RadiositySolution& solution);
    /// Shoots cluster c now; `radius` overrides r_v (tests). Public for tests.
    void shootCluster(size_t c, RadiositySolution& solution, int radius = -1);

    bool singleChannel() const { return m_singleChannel; }
    double maxIlluminanceStep() const;
    std::vector<ClusterLight> clusterLight() const;
    const ShootingStatistics& statistics() const;
    /// Unshot flux in lm: Σ π |Y(ΔL_i)| A_i over patches.
    double unshotFlux() const;

  private:
    bool m_singleChannel = false;
    bool m_oneThread = false;  ///< a mesh too small for the shots to pay for threads
    std::unique_ptr<ShootingCoreBase> m_core;
};

/// True when every material's reflectance and every light's colour is grey, so the
/// light in the scene is grey everywhere and one channel describes it.
bool isGreyScene(const scene::Scene& scene, const PatchMesh& mesh);

}  // namespace rayrad::radiosity
