#include <app/solve_summary.h>

#include <radiosity/radiosity.h>

#include <fmt/format.h>

namespace rayrad::app {

void printSolveSummary(const PipelineRun& run) {
    const auto& s = run.lighting.solution;
    auto balance = energyBalanceOf(run);
    fmt::print(stderr,
               "patches: {}, channels: {}, shots: {}, unshot: {:.4g}% of the {:.6g} lm emitted ({:.4g}% of the first "
               "reflection; {})\n",
               run.mesh.patches.size(), run.lighting.singleChannel ? "1 (grey scene)" : "3", s.shots,
               100 * s.unshotFraction(), s.unshotReference(),
               s.initialUnshotFlux > 0 ? 100 * s.remainingUnshotFlux / s.initialUnshotFlux : 0.0,
               s.converged ? "converged" : "NOT converged: " + run.lighting.shooting.stopReason);
    if (run.lighting.shooting.overshootStalled)
        fmt::print(stderr, "note: overshooting was switched off during the solve: the residual stalled with it\n");
    fmt::print(stderr, "{}\n", run.lighting.clustering.statistics());
    if (run.embree && !run.embree->convexEnclosure().empty())
        fmt::print(stderr,
                   "visibility: the scene is one convex enclosure ({} planes): nothing can shadow a point inside "
                   "it from another, and those shadow rays are not traced\n",
                   run.embree->convexEnclosure().planeCount());
    const auto& g = run.lighting.displayVertices;
    if (g.seams + g.contacts + g.rims + g.extrapolated > 0)
        fmt::print(stderr,
                   "vertices from a point gather: {} on seams (concave edges and corners), {} beside outlines "
                   "crossing patches (objects standing on a surface off its mesh lines), {} on the rims of "
                   "covered parts (a lamp just below a ceiling), {} where the reconstruction extrapolated "
                   "(a face a few patches wide)\n",
                   g.seams, g.contacts, g.rims, g.extrapolated);
    if (!run.lighting.solution.seamProfiles.empty())
        fmt::print(stderr, "seam profiles: {} edges from seam vertices graded toward the seam ({} point gathers)\n",
                   run.lighting.solution.seamProfiles.edgeCount(), run.lighting.seamProfileGathers);
    if (run.lighting.sensorGathers > 0)
        fmt::print(stderr, "sensor gathers: {} for {} sensors (corner and midpoint re-gathers near edges)\n",
                   run.lighting.sensorGathers, run.sensors.size());
    if (run.lighting.clustering.enabled) {
        const auto& t = run.lighting.shooting;
        const std::string throughImages =
            t.imageTransfers > 0
                ? fmt::format(" ({} from mirror images, {:.1f} % of those carrying light)", t.imageTransfers,
                              100.0 * static_cast<double>(t.imageTransfersLit) / t.imageTransfers)
                : "";
        fmt::print(
            stderr,
            "transfers: {} cluster→cluster{} ({} split by a shadow's edge), {} patch→patch pairs, {} corrections, "
            "{} push-pulls; ΔI_max {:.4g} lx\n",
            t.clusterTransfers, throughImages, t.splitTransfers, t.patchPairs, t.corrections, t.pushPulls,
            run.lighting.maxIlluminanceStep);
    }
    std::string alsoAbsorbed;
    if (!run.scene.mirrors.empty() && run.scene.mirrorImages.imageMethod())
        alsoAbsorbed += fmt::format(" + {:.6g} lm by mirrors", balance.mirrorAbsorbed);
    if (balance.backAbsorbed > 0)
        alsoAbsorbed += fmt::format(" + {:.6g} lm on backs of one-sided surfaces", balance.backAbsorbed);
    // Daylight: what came in through the openings, and what the room reflected out again.
    const bool daylight = run.lighting.lights && run.lighting.lights->openingCount() > 0;
    fmt::print(stderr,
               "energy: {} {:.6g} lm, absorbed {:.6g} lm{}{}, unshot {:.6g} lm, not accounted {:+.4f}% "
               "(direct pass {:+.4f}%, secondary pass {:+.4f}%)\n",
               daylight ? "daylight in (through the openings, and the sun outdoors)" : "emitted", balance.emitted,
               balance.absorbed, alsoAbsorbed.empty() ? "" : " (" + alsoAbsorbed.substr(3) + ")",
               daylight ? fmt::format(", left again (through the openings, to the sky) {:.6g} lm, passed straight "
                                      "through (in at one opening, out at another) {:.6g} lm",
                                      balance.leftThroughOpenings, balance.passedThrough)
                        : "",
               balance.unshot, 100 * balance.relativeError(), 100 * balance.directError(),
               100 * balance.secondaryError());
    const auto& st = run.lighting.shooting;
    fmt::print(
        stderr, "closure: {:.3g}% of reflected light escapes; per-shot energy conservation {}{}; overshooting {}\n",
        100 * st.escapeFraction, st.conserving ? "on" : "off (" + st.conservationOff + ")",
        st.conserving ? fmt::format(" (largest adjustment {:.3g}%, {} shots beyond the {:.0f}% bound left alone)",
                                    100 * st.largestRescale, st.unbalancedShots, 100 * radiosity::kConservationBound)
        : st.cappedShots > 0 || st.unbalancedShots > 0
            ? fmt::format(", but {} shots that delivered more than they shipped were scaled down to it (by up to "
                          "{:.3g}%; {} beyond the {:.0f}% bound left alone)",
                          st.cappedShots, 100 * st.largestRescale, st.unbalancedShots,
                          100 * radiosity::kConservationBound)
            : "",
        st.overshooting ? "on" : "off");
}

}  // namespace rayrad::app
