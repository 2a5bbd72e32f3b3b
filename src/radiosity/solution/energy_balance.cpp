#include <radiosity/solution/energy_balance.h>

#include <radiosity/mesh/patch_reflectance.h>

namespace rayrad::radiosity {

EnergyBalance energyBalance(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& s,
                            double emittedFlux) {
    EnergyBalance b;
    b.emitted = emittedFlux + s.outdoorDirect;  // daylight: what came in, and the sun on outdoor surfaces
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        const Rgb rho = patchReflectance(scene, mesh, i);
        Rgb e = s.directMean[i] + (s.indirect.empty() ? Rgb(0.0) : s.indirect[i]);
        b.absorbed += luminance((Rgb(1.0) - rho) * e) * p.area;
        b.directReceived += luminance(s.directMean[i]) * p.area;
    }
    b.unshot = s.unshotNetFlux;
    b.mirrorAbsorbedDirect = s.mirrorAbsorbedDirect;
    b.backAbsorbed = s.backAbsorbedDirect;
    b.leftThroughOpenings = s.leftThroughOpenings;
    b.passedThrough = s.passedThrough;
    b.mirrorAbsorbed = s.mirrorAbsorbedDirect + s.mirrorAbsorbedSecondary;
    return b;
}

}  // namespace rayrad::radiosity
