// The knobs of each stage, filled from the scene file and the command line (--set).
#pragma once

#include <cstdint>
#include <string>

namespace rayrad::scene {

/// How a camera maps pixels to rays.
enum class Projection {
    Perspective,   ///< a pinhole: vfov_deg across the image height
    Fisheye,       ///< equidistant 180°: the angle from the axis grows linearly to 90° at the rim of the
                   ///< largest circle in the image (black outside it); glare and daylight studies
    Orthographic,  ///< parallel rays: a plan or elevation `orthoHeight` metres high
};

/// Premeshing: how input polygons become radiosity patches (`radiosity.max_edge`, ...).
struct MeshingOptions {
    /// false: no premeshing — each input polygon is only triangulated (a quad gives two
    /// triangles), for comparisons with badly shaped input.
    bool premesh = true;
    /// Longest allowed triangle leg (grid cell side) in metres; 0 = 1/20 of the scene's
    /// bounding-box diagonal.
    double maxEdge = 0.0;
    /// If > 0, overrides maxEdge: about this many triangles per input surface
    /// (a quad becomes 2·n_u·n_v triangles, so 800 gives a 20×20 grid on a square).
    int trianglesPerSurface = 0;
    /// Largest aspect ratio of grid cells; thin quads get more cells across.
    double maxCellAspect = 2.0;
    /// Mesh files: where two triangles around a shared vertex meet at more than this angle
    /// (a box's edge), each side gets its own vertex, so the display values on one face are
    /// never averaged with the light of the other; 0 keeps the vertices as the file shares
    /// them. Above the 30-36° between the facets of a coarse sphere or a 10-sided column,
    /// below a 45° chamfer.
    double creaseAngleDeg = 40;
    /// The most patches a scene may be premeshed into (estimated before premeshing, so a
    /// tiny max_edge is an error rather than an allocation that fails). About 1 KiB each.
    double maxPatches = 4e6;
};

/// Clustering for the secondary pass (a voxel grid; two levels: clusters and patches).
/// The voxel size is taken from the first of: voxelSize, patchesPerCluster, sizePercent.
struct ClusterOptions {
    bool enabled = true;           ///< false: every patch shoots and receives on its own
    double voxelSize = 0;          ///< voxel edge in metres (0 = derive)
    double patchesPerCluster = 0;  ///< target average patches per cluster (0 = off)
    /// Cluster size as a percentage of the reference area (the paper's "1 % of the wall
    /// area"): voxel edge = sqrt(sizePercent/100 · referenceArea).
    double sizePercent = 1.0;
    double referenceArea = 0;  ///< m²; 0 = the area of the largest input surface
    /// A derived voxel edge (patchesPerCluster or sizePercent) shrinks by √2 at a time
    /// while a patch shares its voxel with more than this many patches on average
    /// (Σ_v n_v² / N, n_v the patches whose centroid lies in voxel v): patches of one
    /// voxel always exchange patch→patch, so this is the near field's size. A dense
    /// imported mesh (a sofa of 16 k triangles) otherwise fills a voxel. 0 = off.
    double maxVoxelCrowding = 4000;
    double normalToleranceDeg =
        20;  ///< patches of one cluster have normals within this of the first (curved clusters: docs/validation.md)
    /// ΔI_max in lx: cluster→cluster transfer only where one shot of the cluster's total
    /// power would give the receiver less than this. 0 = derive: 20 % of the mean
    /// illuminance (direct + estimated indirect) over the scene (see docs/validation.md).
    double maxIlluminanceStep = 0;
    bool energyCorrection = true;  ///< the paper's energy-transfer correction
    /// How a cluster→cluster shot is shared among the receiver's patches. false (the
    /// paper, eq. 2): I_C pushed down uniformly. true: scaled for each patch by its own
    /// kernel cosθ_j cosθ_C / r_j² from the source cluster relative to the centroid's, so
    /// patches at grazing angles (along edges) do not get the cluster centre's light.
    bool receiverDetail = true;
    /// Push-pull every cluster after this fraction of the unshot power has been shot.
    double pushPullFraction = 0.1;
};

/// The direct pass over the patches (`radiosity.area_light_samples`).
struct DirectOptions {
    /// Shadow-ray samples on each area light for the direct light at patch points.
    int areaLightSamples = 16;
};

/// Point-to-polygon form factors, in the shooting and in the gather (`radiosity.analytic_distance`).
struct FormFactorOptions {
    /// Use the analytic polygon form factor when the receiver is closer to the source
    /// than this many source diameters; the point approximation beyond.
    double analyticDistance = 4.0;
};

/// How the radiosity treats planar mirrors (`radiosity.mirrors`, `radiosity.mirror_*`).
struct MirrorImageOptions {
    /// "image": mirrors by the image method (virtual lights and virtual shooters);
    /// "ignore": not in the radiosity (the ray tracer still shows reflections).
    enum class Mode { Image, Ignore };
    Mode mirrors = Mode::Image;
    bool imageMethod() const { return mirrors == Mode::Image; }
    int mirrorDepth = 4;            ///< reflections per image chain
    double mirrorMinWeight = 1e-3;  ///< drop chains whose Π Ks falls below this
    /// Drop chains that could carry less than this share of a uniformly bright room's
    /// light: Π Ks · G / (π A), G the chain's étendue (m² sr), A the surface area.
    double mirrorMinShare = 1e-5;
};

/// The secondary (indirect) pass: progressive shooting (`radiosity.*`).
struct ShootingOptions {
    /// Stop when the unshot flux falls below this fraction of the flux the lights emit
    /// (the paper's rule): shot, it would raise the illuminance, averaged over the
    /// surfaces, by about this fraction.
    double stopUnshot = 1e-3;
    /// Upper bound on shots (0 = none).
    int64_t maxShots = 0;
    /// Upper bound on the secondary pass's wall-clock time in seconds (0 = none). The
    /// solve also stops by itself when its residual stalls (see ShootingCore::step).
    double maxSeconds = 0;
    /// Shooting, patch→patch: a node of the shooter's member tree farther from a receiver
    /// than this many of its diameters sends as one source (0 = every member on its own).
    double shootFarDiameters = 3.0;
    /// Per-shot energy conservation in closed scenes (with mirrors only when every chain
    /// of reflections is modelled): each shot's deliveries (and what the energy
    /// corrections redeliver; through mirrors counted ÷ Π Ks) are scaled so the flux
    /// received equals the flux shot (the form factors of a closed scene sum to 1; the
    /// point approximations and the cluster visibility estimate do not quite). Without
    /// it a sphere at ρ = 0.99 lost 8 % of its light. A shot off by more than
    /// kConservationBound is left alone and counted.
    bool conserveEnergy = true;
    /// Overshooting (Feda & Purgathofer 1992): a shooter also ships the light it will
    /// receive later, estimated by the ambient term ρ_i E_amb / π with
    /// E_amb = π ΔΦ (1 − e) / (A (1 − ρ̄ (1 − e))) (ΔΦ the unshot power, A the surface area,
    /// ρ̄ the mean reflectance, e the escape fraction), and keeps the negative difference
    /// as unshot light. Speeds up near-white (stiff) scenes many times.
    bool overshoot = true;
    /// Solve one channel instead of three when every reflectance and light is grey.
    bool oneChannelWhenGrey = true;
};

/// The final gather at sensors, and at every hit with `render.indirect` "gather"
/// (`radiosity.gather_*`).
struct GatherOptions {
    /// How many levels of gathers there are: the sensor's own, then the corner and midpoint
    /// values of its near patches re-gathered, and theirs … (a local fixed-point iteration
    /// at edges and corners); the last level's near patches take the solution's display
    /// values (vertex values and seam profiles). 0 = patch-constant luminance, no near field.
    int gatherLevels = 2;
    /// The top this many gather levels refine their near patches toward the point with
    /// gathered (not interpolated) indirect light at sub-triangle corners, where that
    /// differs from linear by more than `gatherRefineTolerance` (relative): the indirect
    /// light's singular fall-off into concave edges and corners (0 = off).
    int gatherRefineLevels = 2;
    double gatherRefineTolerance = 0.002;
    /// A part of a cluster (its member tree's nodes) farther than this many of its
    /// diameters counts as one source (0 = every patch on its own).
    double gatherFarDiameters = 3.0;
    /// A near patch's corner and midpoint values are re-gathered only while their weight
    /// — the part of an error in them that reaches the sensor, the product of ρ F along
    /// the chain of gathers, rounded up to a power of ten — is at least this; below, they
    /// are the solution's vertex values (0 = always).
    double gatherMinWeight = 0.15;
};

/// The display values: what the ray tracer interpolates between (`radiosity.reconstruction`,
/// `radiosity.edge_gather_levels`, `radiosity.seam_profile_nodes`).
struct ReconstructionOptions {
    /// Vertex values from centroid values: "average", the paper's plain average of the
    /// triangles around the vertex; "linear", a least-squares plane through the centroid
    /// values of the two rings of triangles around it, evaluated at the vertex (exact for
    /// linear variation, so it does not flatten the fall-off into edges and corners).
    enum class Mode { Linear, Average };
    Mode reconstruction = Mode::Linear;
    bool linear() const { return reconstruction == Mode::Linear; }
    /// Vertices on concave seams (the vertex lies on an edge of a patch of another
    /// surface that faces it: the edges and corners of a room) take their value from a
    /// point gather, iterated this many rounds (0 = off). The indirect light falls
    /// steeply into such seams and no reconstruction from centroid values follows it
    /// (cube C at 19 200 triangles: +5.9 % without, +0.7 % with 3 rounds).
    /// Surfaces that touch without a shared mesh line (a box standing on a floor) are
    /// left to the reconstruction: a floor vertex near the box's foot is not on the seam.
    int edgeGatherLevels = 3;
    /// Display values graded toward concave seams (radiosity/solution/seam_profiles.h): each
    /// mesh edge from a seam vertex into its surface carries the gathered correction to
    /// linear interpolation at 1/2, 1/4 … of its length, this many nodes at most (0 = off,
    /// ≤ kMaxSeamProfileNodes). Without it the band of triangles along a room's edges reads
    /// up to 10 % low (the indirect light's d·ln(1/d) rise away from the seam). Needs
    /// edge_gather_levels > 0.
    int seamProfileNodes = 5;
    static constexpr int kMaxSeamProfileNodes = 5;
};

/// The ray tracer and the sensor gather.
struct RenderOptions {
    int samplesPerPixel = 4;  ///< jittered (stratified) samples per pixel
    uint64_t seed = 1;        ///< the same seed gives the same image
    /// Shadow rays per area light per pixel (⌈n / spp⌉ per sample; fewer for far lights).
    /// 64: the Cornell box at 256² and 16 spp shows no grain in its penumbrae (between two
    /// seeds p95 3.0 % against 8.4 % at 16; the ray trace 1.09 against 0.58 CPU-s).
    int areaLightSamples = 64;
    int sensorAreaLightSamples = 256;  ///< shadow rays per area light at a sensor
    /// Adaptive shadow testing at hits (DirectLight::illuminanceForDisplay): lights are
    /// shadow-tested strongest first until the rest could add less than this fraction of
    /// all the hit receives: the light found and the indirect light (0 = every light tested).
    double directThreshold = 0.02;
    /// A pixel's samples that land on one patch share the far area lights' shadow rays,
    /// traced at the first of them (DirectLight's PixelLightMemo); false: every sample
    /// traces its own.
    bool shareFarShadows = true;
    int maxDepth = 8;  ///< Whitted recursion through mirrors and glass
    /// Display images average a pixel's samples after range compression (weights
    /// 1/(1 + L_s/L_c)), so emitter edges and highlights stay smooth; the EXR keeps the
    /// plain average.
    bool displayRangeCompression = true;
    /// Curved meshes are shaded with normals interpolated across each triangle from the
    /// vertices (the mean normal of the triangles around a corner that meet it within this
    /// angle), so their facets do not show; 0 shades every triangle flat. Images only.
    double smoothingAngleDeg = 30;
    /// Where a hit's indirect light comes from: the radiosity mesh's vertex values, or a
    /// final gather at the hit itself (as at a sensor: no mesh can show, and it is slow — a
    /// reference for judging the mesh's interpolation, `render.indirect` "gather").
    bool gatherIndirect = false;
};

/// Every stage's settings, one struct per stage and sub-stage, in the order of the data
/// flow: what the scene file's "radiosity", "clusters" and "render" objects set (and --set
/// overrides). The scene description and the scene carry them (SceneDesc, Scene).
struct Settings {
    MeshingOptions meshing;
    DirectOptions direct;
    FormFactorOptions formFactors;
    MirrorImageOptions mirrorImages;
    ClusterOptions clusters;
    ShootingOptions shooting;
    GatherOptions gather;
    ReconstructionOptions reconstruction;
    RenderOptions render;
};

}  // namespace rayrad::scene
