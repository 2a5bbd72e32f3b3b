// The knobs of each stage, filled from the scene file and the command line (--set).
#pragma once

#include <cstdint>
#include <string>

namespace rayrad::scene {

/// Premeshing: how input polygons become radiosity patches (`radiosity.max_edge`, ...).
struct MeshingOptions {
    /// Longest allowed triangle leg (grid cell side) in metres; 0 = 1/20 of the scene's
    /// bounding-box diagonal.
    double maxEdge = 0.0;
    /// If > 0, overrides maxEdge: about this many triangles per input surface
    /// (a quad becomes 2·n_u·n_v triangles, so 800 gives a 20×20 grid on a square).
    int trianglesPerSurface = 0;
    /// Largest aspect ratio of grid cells; thin quads get more cells across.
    double maxCellAspect = 2.0;
};

/// The secondary (indirect) pass: progressive shooting.
struct SolverOptions {
    /// Stop when the unshot flux falls below this fraction of the flux the direct pass
    /// left to distribute (the first reflection).
    double stopUnshot = 1e-3;
    /// Upper bound on shots (0 = none).
    int64_t maxShots = 0;
    /// Use the analytic polygon form factor when the receiver is closer to the source
    /// than this many source diameters; the point approximation beyond.
    double analyticDistance = 4.0;
    /// Shadow-ray samples on each area light for the direct light at patch points.
    int areaLightSamples = 16;
    /// Sensor gather: how many times corner values of near patches are themselves
    /// re-gathered (a local fixed-point iteration at edges and corners; 0 = patch-constant).
    int gatherLevels = 8;
};

/// The ray tracer and the sensor gather.
struct RenderOptions {
    int samplesPerPixel = 4;      ///< jittered (stratified) samples per pixel
    uint64_t seed = 1;            ///< the same seed gives the same image
    int areaLightSamples = 16;    ///< shadow rays per area light per hit
    int sensorAreaLightSamples = 256;  ///< shadow rays per area light at a sensor
};

}  // namespace rayrad::scene
