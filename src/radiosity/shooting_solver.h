// Progressive radiosity by shooting: largest unshot power first (the secondary pass).
#pragma once

#include <core/visibility.h>
#include <radiosity/patch_mesh.h>
#include <radiosity/solution.h>
#include <scene/scene.h>
#include <scene/settings.h>

#include <functional>

namespace rayrad::radiosity {

/// The non-clustered shooting iteration (Cohen et al. 1988) over the premeshed patches.
/// Each step picks the patch with the largest unshot power |Y(ΔL)|·A and shoots ΔL to
/// every receiver r:  ΔE_r = π ΔL F(c_r → s) V(c_r, s),  E_r += ΔE_r,  ΔL_r += ρ_r ΔE_r / π.
/// Receivers are independent, so a shot runs in parallel and stays deterministic.
class ShootingSolver {
  public:
    ShootingSolver(const scene::Scene& scene, const PatchMesh& mesh, const Visibility& vis,
                   const scene::SolverOptions& options);

    /// Starts from the direct pass: ΔL_i = ρ_i Ē_direct,i / π, E_indirect = 0.
    void initialize(RadiositySolution& solution) const;
    /// One shot; false (and nothing done) once converged or out of shots.
    bool step(RadiositySolution& solution) const;
    /// Iterates to the stopping rule; `onProgress` is called now and then.
    void solve(RadiositySolution& solution, const std::function<void(const RadiositySolution&)>& onProgress = {}) const;

    /// Unshot flux in lm: Σ π |Y(ΔL_i)| A_i.
    double unshotFlux(const RadiositySolution& solution) const;

  private:
    void shoot(size_t source, RadiositySolution& solution) const;

    const scene::Scene& m_scene;
    const PatchMesh& m_mesh;
    const Visibility& m_vis;
    scene::SolverOptions m_options;
};

/// Energy accounting in lm: what the lights emit, what surfaces absorbed
/// Σ (1 − ρ) (Ē_dir + E_ind) A, and what is still unshot. In a closed scene
/// emitted = absorbed + unshot.
struct EnergyBalance {
    double emitted = 0, absorbed = 0, unshot = 0;
    double relativeError() const { return emitted > 0 ? (absorbed + unshot - emitted) / emitted : 0.0; }
};
EnergyBalance energyBalance(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                            double emittedFlux);

}  // namespace rayrad::radiosity
