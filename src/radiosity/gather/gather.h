// The final gather: indirect illuminance at a point from the converged solution, with
// corner and midpoint values re-gathered near the point (sensors.h uses it).
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters/cluster_tree.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/clusters/far_field.h>
#include <radiosity/clusters/member_tree.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/mesh/mesh_location.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/mirrors/mirror_images.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace rayrad::radiosity {

/// How a Gatherer works: the scene's gather settings (scene::GatherOptions, each named
/// as in the scene file), or a sub-stage's own, and what only the stage sets.
struct GatherOptions : scene::GatherOptions {
    int maxSplitDepth = 12;  ///< sub-triangle refinement toward the point
    /// Near patches narrower than this (m; width 2·area / longest edge) are not refined
    /// with gathered midpoints (their corners are re-gathered as any patch's): an imported
    /// mesh's slivers, a molding's strips, each "near" by its length though millimetres
    /// wide (0 = none). A point in the living room's corner beside a molded baseboard had
    /// 253 such patches among the 317 it re-gathered, and took 57.6 CPU-s.
    double minRefineWidth = 0;
    /// false: every patch its own visibility ray, however far its cluster (with
    /// gatherFarDiameters 0, the exact sum: the reference shared rays are measured against).
    bool sharedRays = true;
    /// false: a gather's sum over the sources runs on the thread that asked for it (a small
    /// mesh's sum is too little work to share; the sensors still run side by side).
    bool parallelSums = true;
    /// The sensors' gather: the scene's settings, and slivers below 1/20 of the mesh's
    /// edge, so no patch the premesher made counts as one.
    static GatherOptions forSensors(const scene::Scene& scene, const PatchMesh& mesh);
    /// A plain gather: patch-constant luminance (no re-gathers, no refinement), every
    /// patch on its own; the stages that need more set it.
    static GatherOptions plain();
};

/// The corner and midpoint values one run of gathers has re-gathered, and how many
/// gathers it took. A run's values depend on what it gathered before (see Gatherer), so
/// a memo serves one thread at a time; runs with memos of their own are independent of
/// each other and of the order they run in.
class GatherMemo {
  public:
    /// Point gathers taken so far: the sensors' own and every corner and midpoint re-gather.
    size_t gathers() const { return m_gathers; }

  private:
    friend class Gatherer;
    /// A re-gathered value and the finest weight class it was gathered for.
    struct Entry {
        Rgb indirect;
        int weightClass;
    };
    /// (vertex or midpoint id, level) → indirect (lx, RGB).
    using Key = std::pair<uint64_t, int>;
    /// An entry for `key`'s id gathered at `key`'s level or higher and in at least the
    /// detail of `weightClass`, if there is one.
    static const Rgb* recall(const std::map<Key, Entry>& memo, const Key& key, int weightClass);
    std::map<Key, Entry> m_vertex;
    std::map<std::pair<uint64_t, uint64_t>, uint64_t> m_midpointIds;  ///< (a, b) sorted → id
    std::map<Key, Entry> m_midpoint;
    size_t m_gathers = 0;
};

/// Final gather of the indirect illuminance into a differential area at x:
///   E_ind(x) = Σ_j ∫_{A_j} L_j(y) cosθ_x cosθ_y / r² V(x, y) dA_y,  L_j = ρ_j E_j / π.
/// Far patches: L_j constant (ρ_j (Ē_dir,j + E_ind,j) / π) with the analytic form factor.
/// Near patches (a point on an edge sees the neighbouring wall at grazing angles, so
/// nearly all of that wall's contribution comes from right beside the point): L_j linear
/// over the triangle from its corner values, integrated exactly (π F L(c_F),
/// form_factor_centroid.h) where x sees a piece whole and over sub-triangles refined
/// toward x where it is partly hidden. Corner values are exact direct light plus indirect
/// light gathered at the corner itself, recursively `levels` deep (memoised), which removes the bias of
/// patch-constant luminance at edges and corners. The last level's corners and midpoints
/// take the solution's display values (vertex values, gathered on seams, contacts and
/// rims, and the seam profiles): the solve's own point gathers end the recursion. Two
/// levels read the cube within 0.07 % RMS of a path tracer beside its edges and corners;
/// one level (no re-gather, one gather a point) is the fast setting, 0.13 % there.
/// Near patches of the top `refineLevels` gathers are refined further: a linear
/// luminance misses the indirect light's fall-off into concave edges and corners (a
/// singular derivative there), so each near triangle is split toward x and its edge
/// midpoints take direct light interpolated from the exact corner values plus *gathered*
/// indirect light, one level down; a piece is split further while a gathered midpoint
/// differs from the interpolation by more than `refineTolerance` (relative; looser in
/// proportion for triangles holding less than 1/20 of the near field's ρ F), at most
/// 6 times — a local graded re-solve around the point.
/// Mirrors: the patches' images are gathered too (patch-constant luminance × Π Ks,
/// seen only through the mirror polygons).
class Gatherer {
  public:
    /// Clusters farther than a few of their diameters from the point share their
    /// visibility rays: two, or four, sampled where their light to the point comes from
    /// (ClusterVisibility in visibility_share.h).
    /// `options.farDiameters` > 0: a node of a cluster's member tree (the whole cluster,
    /// its halves, their halves …) farther than that many of its diameters counts as one
    /// source (a Barnes–Hut far field; see far_field.h) seen through two or four rays
    /// (visibleShare). Nodes holding a near patch are always opened.
    /// A re-gather of weight w < 1 counts nodes as far from farDiameters · ∛w of their
    /// diameters (at least 2): the far field's error falls as the cube of the distance, and
    /// reaches the sensor times w. It also takes whole groups of clusters (ClusterTree)
    /// that far as one source each, seen through two visibility rays (four where they
    /// disagree: a group spans more than a cluster, and one ray made two sensors at one
    /// place differ by 1.2e-4 in a room with desks), where the group faces
    /// one way (its normals within the clusters' normal tolerance; and only where there are
    /// clusters). The re-gathers of the cube grid's edge sensors take 212 sources each
    /// (104 clusters, 108 groups) instead of 600 clusters: the grid's sensor stage went
    /// from 0.86–0.89 to 0.54–0.73 × the solve, its error against the path tracer unchanged.
    /// `options.minWeight` > 0: corner and midpoint values are re-gathered only where an
    /// error in them can still reach the sensor by that fraction. Without it, a point
    /// beside a dense mesh (near patches by the hundred, each re-gathering its corners,
    /// `levels` deep) costs thousands of gathers; with it, the recursion follows the walls
    /// of concave edges and corners, and leaves a sofa's slivers at their solution values.
    /// Weights are rounded up to a power of ten (a weight class). A memoised value
    /// gathered for a larger weight (in more detail), or at a higher level (with a deeper
    /// recursion below it), serves a request for less, so a sensor's value can depend on
    /// the sensors gathered before it with the same memo (GatherMemo), by less than the
    /// minimum weight times the error of a vertex value (0.1 × 1 % at a cube corner: 1e-3).
    Gatherer(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
             const RadiositySolution& solution, const Visibility& vis, const GatherOptions& options);

    /// Indirect illuminance (lx, RGB) at x with unit normal n; re-gathered corner and
    /// midpoint values are kept in (and taken from) `memo`. Thread-safe for distinct memos.
    /// `expected` (lx, > 0 when known: the mesh's interpolated value there) says which far
    /// sources matter: those bringing at least 1/1000 of it take four visibility rays,
    /// the others one (see gatherWith); 0: two, or four where those disagree.
    Rgb indirectAt(const Vec3& x, const Vec3& n, GatherMemo& memo, double expected = 0) const {
        return gather(x, n, m_options.gatherLevels, 0, memo, expected);
    }

    /// Indirect illuminance of a patch corner (patch, corner index) — lx, RGB. `share`:
    /// ρ F of the patch seen from the gathering point, the part of an error in the value
    /// that reaches that gather.
    using CornerSource = std::function<Rgb(size_t patch, int corner, double share)>;
    /// The point y halfway between points a and b of a near patch (ids: a mesh vertex,
    /// or an earlier midpoint): its id and its gathered indirect illuminance (lx, RGB).
    /// Ids, not positions, say which points are the same: the two sides of a contact
    /// line share positions but not vertices.
    struct Midpoint {
        uint64_t id;
        Rgb indirect;
    };
    using MidpointSource = std::function<Midpoint(size_t patch, uint64_t a, uint64_t b, const Vec3& y, double share)>;
    /// Which part of the sum a gather returns (see Request::part).
    enum class Part { All, Near, AllButNear };
    /// Serial: for callers that are parallel themselves.
    enum class Threads { Parallel, Serial };

    /// One point gather: where, how the near patches are valued, and what of the sum.
    struct Request {
        Request() = default;
        Request(const Vec3& x, const Vec3& n, const CornerSource* corners = nullptr,
                Threads threads = Threads::Parallel)
            : x(x), n(n), corners(corners), threads(threads) {}
        Vec3 x{0.0}, n{0.0};  ///< the point and its unit normal
        /// With corners, near patches get linear luminance from exact direct light plus
        /// these indirect corner values; without, patch-constant.
        const CornerSource* corners = nullptr;
        /// With midpoints too, near patches are refined toward x with gathered indirect
        /// light at their sub-triangles' corners (see the class comment).
        const MidpointSource* midpoints = nullptr;
        Threads threads = Threads::Parallel;
        /// How much of an error in this gather reaches the sensor (the product of ρ F along
        /// the chain of gathers that asked for it; 1 for the sensor's own). With a minimum
        /// weight (gatherMinWeight), the near patches of smallest share (ρ F), as many as
        /// keep the sum of their shares within gatherMinWeight / weight, take their corner
        /// values from the solution and are not refined; the others are refined to the
        /// tolerance / weight, so the error either brings to the sensor is bounded alike.
        double weight = 1;
        /// With corners, the sum split in two that add up to the whole: the near patches'
        /// linear luminance alone (the only part that depends on the corner values), or
        /// everything else (far clusters, other patches, mirror images).
        Part part = Part::All;
        /// The indirect illuminance (lx) x is expected to receive, as for indirectAt.
        double expected = 0;
        /// From nearPatches: the near patches are these rather than those near x — the same
        /// set for every point of a segment (the seam profiles compare the near parts of
        /// points along an edge), found once.
        const std::vector<uint32_t>* nearSet = nullptr;
    };
    /// Indirect illuminance (lx, RGB) of one gather.
    Rgb gatherWith(const Request& request) const;

    /// The patches whose centroid lies within two of their own diameters (kNearDiameters)
    /// of the segment [a, b] (a == b: of a point), in cluster order: a gather's near
    /// patches, before the facing test.
    struct Segment {
        Vec3 a, b;
    };
    std::vector<uint32_t> nearPatches(const Segment& along) const;

  private:
    /// A piece of a near patch with the luminance at its corners (cd/m², RGB).
    struct NearPiece {
        std::array<Vec3, 3> p;
        std::array<Rgb, 3> L;
        int depth;  ///< subdivision depth already spent
    };
    /// A corner of a piece being refined: position, id (see Midpoint), luminance
    /// (cd/m²) and direct illuminance (lx).
    struct RefinePoint {
        Vec3 p;
        uint64_t id;
        Rgb L, E;
    };
    struct NearPatch;
    struct NearCluster;
    struct NearField;
    struct PointSources;
    /// The near patches of a gather with corner values (request.corners), with their
    /// pieces (gather_near_field.cpp).
    void findNearField(const Request& request, NearField& near) const;
    /// Near patch e's light at the request's point, piece by piece, added to `into`.
    void addNear(const Request& request, const NearField& near, const NearPatch& e, Rgb& into) const;
    /// What the sum over sources needs of the request (gather_sources.cpp): how far a node
    /// counts as far, and which mirror images and voxels can send the point light.
    PointSources pointSources(const Request& request, const NearField& near) const;
    /// The scene's own items of the sum: its clusters, or in a re-gather groups of far
    /// clusters too (index clusters + g for group g).
    std::vector<uint32_t> sceneItems(const PointSources& point) const;
    /// Cluster c's light at the point as source s shows it (0: the scene, i + 1: image i).
    Rgb clusterContribution(const PointSources& point, size_t s, size_t c) const;
    /// Far group `index` of the cluster tree: its light times the share of its rays seen.
    Rgb groupContribution(const PointSources& point, uint32_t index) const;
    /// Σ over every source: the scene items, then every image's open clusters.
    Rgb sumSources(const PointSources& point, const std::vector<uint32_t>& items) const;

    /// A gather whose error reaches the sensor with weight at most 10^−weightClass.
    Rgb gather(const Vec3& x, const Vec3& n, int level, int weightClass, GatherMemo& memo, double expected = 0) const;
    /// The class of a weight: k with 10^−(k+1) < weight ≤ 10^−k, so a class's weight is at
    /// least that of its members (always 0 without a minimum weight: every gather is then
    /// in full detail).
    int classOf(double weight) const;
    Rgb cornerIndirect(size_t patch, int corner, int level, int weightClass, GatherMemo& memo) const;
    Midpoint midpointIndirect(size_t patch, uint64_t a, uint64_t b, const Vec3& y, int level, int weightClass,
                              GatherMemo& memo) const;
    /// The solution's own indirect illuminance at a patch corner (lx): the vertex value,
    /// or the patch's when there are none.
    Rgb solutionCorner(size_t patch, int corner) const;
    /// Splits the triangle c toward x while its gathered midpoints differ from the
    /// linear interpolation; the pieces are appended.
    void refineNear(const Vec3& x, size_t patch, const std::array<RefinePoint, 3>& c, int depth,
                    const MidpointSource* midpoints, double share, double tolerance,
                    std::vector<NearPiece>& pieces) const;
    /// E at x from the triangle p of linear luminance L, split toward x while closer than
    /// its size. `knownF` ≥ 0: the triangle's form factor, already computed (a near
    /// patch left whole), used when it is not split. `view`: p's vertices as x sees them
    /// (viewFrom), shared by a split's children.
    /// `wholeIfSeen`: a piece closer than its size that x sees wholly (seenWhole) is
    /// integrated exactly in one step, π F L(c_F); one partly hidden is split, and its
    /// pieces are not asked again.
    Rgb integrateLinear(const Vec3& x, const Vec3& n, const Vec3 p[3], const VertexView view[3], const Rgb L[3],
                        const Vec3& normal, int depth, double knownF, bool wholeIfSeen) const;
    /// True when the visibility rays from x to the triangle's `lightCentre` (its form
    /// factor's centroid) and to a point toward each corner all pass.
    bool seenWhole(const Vec3& x, const Vec3& n, const Vec3 p[3], const Vec3& lightCentre) const;
    Rgb integrateLinear(const Vec3& x, const Vec3& n, const Vec3 p[3], const Rgb L[3], const Vec3& normal, int depth,
                        double knownF = -1) const;

    const scene::Scene& m_scene;
    const PatchMesh& m_mesh;
    const Clustering& m_clustering;
    const RadiositySolution& m_solution;
    const Visibility& m_vis;
    GatherOptions m_options;
    double m_nudge;
    std::vector<double> m_clusterPatchSize;     ///< largest member diameter per cluster
    std::vector<MemberTree> m_trees;            ///< per cluster
    std::vector<std::vector<FarSource>> m_far;  ///< per cluster, per node of its tree
    std::vector<FarSource> m_rootFar;           ///< per cluster, its root's (m_far[c][0]), contiguous
    std::vector<uint32_t> m_treePosition;       ///< per patch, its position in its tree's order
    ClusterTree m_clusterTree;                  ///< groups of clusters, far sources in re-gathers
    double m_groupCone =
        0;  ///< a group is one source only while its normals are this close (radians; ClusterGroup::coneAngle)
    std::vector<std::unique_ptr<MirrorView>> m_mirrorViews;
    /// Per image i, per cluster: some member faces the chain's first mirror (clustersFacing);
    /// the others send nothing into the image.
    std::vector<std::vector<char>> m_imageSends;
    std::vector<uint64_t> m_sourceKeys;  ///< per source s (0: the scene, i + 1: image i), for visibilityOffset
    VoxelRegions m_regions;              ///< a gather through a mirror skips the voxels no light passes from
};

}  // namespace rayrad::radiosity
