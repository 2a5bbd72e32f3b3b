// The secondary pass: progressive shooting over the two-level hierarchy (clusters, patches).
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>
#include <scene/settings.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rayrad::radiosity {

/// The light a cluster holds during the solve (Myszkowski & Kunii, eq. 1–2).
struct ClusterLight {
    Rgb unshot{0.0};    ///< ΔL_C = Σ ΔL_i A_i / A_C, cd/m² (kept current as patches receive)
    Rgb total{0.0};     ///< L_C = Σ L_i A_i / A_C, cd/m²
    /// ρ I / π of the cluster→cluster illuminance received but not yet pushed down:
    /// the reflected luminance it will add, area-averaged, cd/m² (for choosing shooters).
    Rgb pendingReflected{0.0};
    int radius = 0;     ///< r_v of the last shot, in voxels (0 = never shot)
};

/// Per-shot conservation adjusts a shot's deliveries by at most this fraction: a larger
/// deficit is not a closed scene's rounding, and the shot is left as it is (counted).
constexpr double kConservationBound = 3.0;

/// Counters of what the solve did.
struct ShootingStatistics {
    int64_t clusterTransfers = 0;  ///< cluster→cluster receivers
    /// Of those, split by a shadow's edge (sample rays disagreeing): each member its own ray.
    int64_t splitTransfers = 0;
    /// Of those, from a mirror image, and how many of them carried light (F V > 0): the
    /// rest were tested and found dark through the chain's apertures.
    int64_t imageTransfers = 0, imageTransfersLit = 0;
    int64_t patchPairs = 0;        ///< patch→patch terms evaluated: per receiver patch, each sending member or far member-tree node
    int64_t corrections = 0;       ///< receiver clusters corrected
    int64_t pushPulls = 0;         ///< global push-pulls
    double escapeFraction = 0;     ///< of rays leaving the surfaces (0: a closed scene)
    bool conserving = false;       ///< per-shot energy conservation applied
    std::string conservationOff;   ///< why not: "open scene", "mirrors ignored", ...
    double largestRescale = 0;     ///< max |scale − 1| applied to a shot by the conservation
    int64_t unbalancedShots = 0;   ///< shots the conservation left alone (deficit beyond its bound)
    double mirrorAbsorbed = 0;     ///< lm the mirrors absorbed of what images delivered (delivered · (1/Π Ks − 1))
    bool overshooting = false;
    /// Overshooting was switched off during the solve because the residual stalled.
    bool overshootStalled = false;
    /// Why the solve stopped before converging ("" when it converged or has not run).
    std::string stopReason;
};

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
                   const Visibility& vis, const scene::SolverOptions& solver, const scene::ClusterOptions& clusters);
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
    std::unique_ptr<ShootingCoreBase> m_core;
};

/// True when every material's reflectance and every light's colour is grey, so the
/// light in the scene is grey everywhere and one channel describes it.
bool isGreyScene(const scene::Scene& scene, const PatchMesh& mesh);

/// Energy accounting in lm: what the lights emit, what surfaces absorbed
/// Σ (1 − ρ) (Ē_dir + E_ind) A, what is still unshot, and what the direct pass delivered
/// first, Σ Ē_dir A, what mirrors absorbed, and what fell on the backs of one-sided
/// surfaces (absorbed there). In a closed scene emitted = absorbed + mirrors + backs +
/// unshot; the direct pass's share of any difference is its patch-mean quadrature (or
/// light escaping, or lost beyond the mirror chains' depth), the rest is the secondary
/// pass's.
struct EnergyBalance {
    double emitted = 0, absorbed = 0, unshot = 0, directReceived = 0;
    /// lm absorbed by mirrors (booked by the images that deliver through them), of it in the direct pass.
    double mirrorAbsorbed = 0, mirrorAbsorbedDirect = 0;
    /// lm the direct pass delivered onto backs of one-sided surfaces.
    double backAbsorbed = 0;
    double relativeError() const { return relative(absorbed + mirrorAbsorbed + backAbsorbed + unshot - emitted); }
    double directError() const { return relative(directReceived + mirrorAbsorbedDirect + backAbsorbed - emitted); }
    /// What the secondary pass lost or made.
    double secondaryError() const {
        return relative(absorbed + mirrorAbsorbed + unshot - directReceived - mirrorAbsorbedDirect);
    }
    double backShare() const { return relative(backAbsorbed); }

  private:
    double relative(double flux) const { return emitted > 0 ? flux / emitted : 0.0; }
};
EnergyBalance energyBalance(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                            double emittedFlux);

}  // namespace rayrad::radiosity
