// Energy accounting of a solution in lm: emitted, absorbed, unshot, and where the rest went.
#pragma once

#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

namespace rayrad::radiosity {

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
    /// lm reflected out of the scene through its openings (daylight).
    double leftThroughOpenings = 0;
    /// lm that came in through an opening and left through one without meeting a surface.
    double passedThrough = 0;
    double relativeError() const {
        return relative(absorbed + mirrorAbsorbed + backAbsorbed + unshot + leftThroughOpenings + passedThrough -
                        emitted);
    }
    double directError() const {
        return relative(directReceived + mirrorAbsorbedDirect + backAbsorbed + passedThrough - emitted);
    }
    /// What the secondary pass lost or made.
    double secondaryError() const {
        return relative(absorbed + mirrorAbsorbed + unshot + leftThroughOpenings - directReceived -
                        mirrorAbsorbedDirect);
    }
    double backShare() const { return relative(backAbsorbed); }

  private:
    double relative(double flux) const { return emitted > 0 ? flux / emitted : 0.0; }
};
EnergyBalance energyBalance(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                            double emittedFlux);

}  // namespace rayrad::radiosity
