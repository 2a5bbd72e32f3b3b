// What the shooting holds per cluster and counts while it runs.
#pragma once

#include <core/math.h>

#include <cstdint>
#include <string>

namespace rayrad::radiosity {

/// The light a cluster holds during the solve (Myszkowski & Kunii, eq. 1–2).
struct ClusterLight {
    Rgb unshot{0.0};  ///< ΔL_C = Σ ΔL_i A_i / A_C, cd/m² (kept current as patches receive)
    Rgb total{0.0};   ///< L_C = Σ L_i A_i / A_C, cd/m²
    /// ρ I / π of the cluster→cluster illuminance received but not yet pushed down:
    /// the reflected luminance it will add, area-averaged, cd/m² (for choosing shooters).
    Rgb pendingReflected{0.0};
    int radius = 0;  ///< r_v of the last shot, in voxels (0 = never shot)
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
    int64_t patchPairs =
        0;  ///< patch→patch terms evaluated: per receiver patch, each sending member or far member-tree node
    int64_t corrections = 0;      ///< receiver clusters corrected
    int64_t pushPulls = 0;        ///< global push-pulls
    double escapeFraction = 0;    ///< of rays leaving the surfaces (0: a closed scene)
    bool conserving = false;      ///< per-shot energy conservation applied
    std::string conservationOff;  ///< why not: "open scene", "mirrors ignored", ...
    double largestRescale = 0;    ///< max |scale − 1| applied to a shot by the conservation
    int64_t unbalancedShots = 0;  ///< shots the conservation left alone (deficit beyond its bound)
    /// Open scene: shots that delivered more than they shipped, scaled down to it.
    int64_t cappedShots = 0;
    double mirrorAbsorbed = 0;    ///< lm the mirrors absorbed of what images delivered (delivered · (1/Π Ks − 1))
    bool overshooting = false;
    /// Overshooting was switched off during the solve because the residual stalled.
    bool overshootStalled = false;
    /// Why the solve stopped before converging ("" when it converged or has not run).
    std::string stopReason;
};

}  // namespace rayrad::radiosity
