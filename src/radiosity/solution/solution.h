// The radiosity solution: per-patch direct and indirect illuminance, per-vertex indirect.
#pragma once

#include <core/math.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/mesh/patch_reflectance.h>
#include <radiosity/solution/seam_profiles.h>
#include <scene/scene.h>

#include <array>
#include <vector>

namespace rayrad::radiosity {

/// What the secondary pass leaves for the ray tracer and the sensors. All illuminances
/// in lx (RGB), luminances in cd/m² (RGB).
struct RadiositySolution {
    std::vector<Rgb> directMean;      ///< mean direct illuminance over each patch
    std::vector<RgbF> directCorner;   ///< direct illuminance at each patch's 3 corners (3·i + k), float
    std::vector<Rgb> indirect;        ///< indirect illuminance received at each patch (centroid)
    std::vector<Rgb> vertexIndirect;  ///< indirect at each mesh vertex (average of its triangles)
    /// Corrections graded toward concave seams, added to the vertex interpolation (empty:
    /// none; seam_profiles.h).
    SeamProfiles seamProfiles;

    // Statistics of the solve.
    int64_t shots = 0;
    double emittedFlux = 0;          ///< lm the lights emit (set by the direct pass)
    double initialUnshotFlux = 0;    ///< lm left to distribute after the direct pass
    double remainingUnshotFlux = 0;  ///< lm still unshot at the end: Σ π |Y(ΔL_i)| A_i
    /// The same net of sign, Σ π Y(ΔL_i) A_i (lm; ΔL_i may be negative after corrections
    /// and overshooting): the unshot term of the energy balance. The solve keeps no
    /// per-patch ΔL beyond its own end (24 bytes per patch nothing else reads).
    double unshotNetFlux = 0;
    /// The flux the unshot fractions are of, lm: the emitted flux (radiosity.stop_unshot),
    /// or, in a solution without lights (tests that set the direct light by hand), the
    /// first reflection.
    double unshotReference() const { return emittedFlux > 0 ? emittedFlux : initialUnshotFlux; }
    /// The unshot flux still to distribute as a fraction of unshotReference().
    double unshotFraction() const { return unshotReference() > 0 ? remainingUnshotFlux / unshotReference() : 0.0; }
    bool converged = false;
    double seconds = 0;
    /// lm absorbed by mirrors on the way, booked by the source that delivers through
    /// them (delivered · (1/Π Ks − 1)): in the direct pass, and in the secondary pass.
    double mirrorAbsorbedDirect = 0, mirrorAbsorbedSecondary = 0;
    /// lm the surfaces reflect out through the openings (daylight), over the whole solution.
    double leftThroughOpenings = 0;
    /// lm that comes in through an opening and leaves through one without meeting a surface.
    double passedThrough = 0;
    /// lm the sun delivers onto surfaces from outdoors (not through an opening): light
    /// that enters the account there, besides what enters through the openings.
    double outdoorDirect = 0;
    /// lm the direct pass delivered onto the backs of one-sided surfaces (absorbed there:
    /// a one-sided surface's back is the inside of a solid, or a modelling error), and
    /// onto the backs of mirrors; per surface group (scene.groups) and in all.
    std::vector<double> backFlux;
    double backAbsorbedDirect = 0;

    /// Reflected (non-emitted) luminance of patch i: ρ (E_direct + E_indirect) / π.
    Rgb reflectedLuminance(const scene::Scene& scene, const PatchMesh& mesh, size_t i) const {
        return patchReflectance(scene, mesh, i) * (directMean[i] + indirect[i]) / kPi;
    }
};

/// The vertex values of patch p's corners weighted by w (lx, RGB).
Rgb weightedVertexIndirect(const PatchMesh& mesh, const RadiositySolution& solution, size_t patch,
                           const std::array<double, 3>& w);

/// Indirect at barycentric (u, v) of patch p, interpolated from the vertex values (inside a
/// patch a contact outline crosses, from the corners on the point's side: sameSideWeights),
/// plus the seam profiles' correction in the band beside a concave seam.
Rgb interpolateIndirect(const PatchMesh& mesh, const RadiositySolution& solution, size_t patch, double u, double v);

}  // namespace rayrad::radiosity
