// The shooting iteration itself, for one grey channel or three (see shooting_solver.h).
#pragma once

#include <radiosity/clusters/far_field.h>
#include <radiosity/clusters/image_clusters.h>
#include <radiosity/clusters/member_tree.h>
#include <radiosity/mirrors/mirror_images.h>
#include <radiosity/shooting/closure.h>
#include <radiosity/shooting/cluster_transfer.h>
#include <radiosity/shooting/shooting_statistics.h>
#include <radiosity/solution/light_value.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>
#include <scene/settings.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

namespace rayrad::radiosity {

/// What ShootingSolver forwards to; one implementation per value type.
class ShootingCoreBase {
  public:
    virtual ~ShootingCoreBase() = default;
    virtual void initialize(RadiositySolution& s) = 0;
    virtual bool step(RadiositySolution& s, bool sync) = 0;
    virtual void pushPullAll() = 0;
    virtual void shootCluster(size_t c, int radius) = 0;
    /// Unshot flux in lm: Σ π |Y(ΔL_i)| A_i over patches.
    virtual double unshotFlux() const = 0;
    virtual bool pushPullDue() const = 0;
    virtual double maxIlluminanceStep() const = 0;
    virtual std::vector<ClusterLight> clusterLight() const = 0;
    virtual const ShootingStatistics& statistics() const = 0;
    /// Writes the working values into the solution: its indirect array (RGB) and unshot
    /// net flux.
    virtual void sync(RadiositySolution& s) const = 0;
    /// sync() for the last time: frees the per-patch arrays only the shots read first (the
    /// shot's scratch, pending light, reflectances, direct light), then the rest once the
    /// solution has its copy, so the solution's array never coexists with all of the
    /// solver's. The core cannot shoot after this; statistics, the unshot flux and the
    /// cluster values stay.
    virtual void finish(RadiositySolution& s) = 0;
};

/// The solver's state and steps for light values of type V (double or Rgb). Working
/// arrays are the solver's own; the solution gets them at sync() and finish().
template <class V>
class ShootingCore final : public ShootingCoreBase {
  public:
    ShootingCore(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering, const Visibility& vis);

    void initialize(RadiositySolution& s) override;
    bool step(RadiositySolution& s, bool sync) override;
    void pushPullAll() override;
    void shootCluster(size_t c, int radius) override;
    double unshotFlux() const override;
    bool pushPullDue() const override {
        return m_shotSincePushPull > m_clusterOptions.pushPullFraction * m_powerAtPushPull;
    }
    double maxIlluminanceStep() const override { return m_maxStep; }
    std::vector<ClusterLight> clusterLight() const override;
    const ShootingStatistics& statistics() const override { return m_stats; }
    void sync(RadiositySolution& s) const override;
    void finish(RadiositySolution& s) override;
    /// Σ π Y(ΔL_i) A_i in lm, signed (RadiositySolution::unshotNetFlux).
    double unshotNetFlux() const;

  private:
    /// Where a shot comes from: the real scene, or its image in a chain of mirrors
    /// (virtual shooters: mirrored patches and clusters, weight Π Ks, seen only through
    /// the mirrors). Receivers are always the real patches.
    struct Source {
        const Visibility* vis;
        V weight;
        const MirrorImage* image;  ///< null for the real scene
        /// Images only, per cluster: some patch in front of the chain's first mirror (it
        /// can send through the chain) / of its last mirror (it can receive). Static.
        std::vector<char> sends, receives;
    };
    /// The shooting cluster as one source shows it: the real cluster and mesh, or an
    /// image's copy of the cluster alone (built per shot; see imageCluster).
    struct Shooter {
        const PatchMesh& realMesh;
        const Cluster& real;
        std::optional<ImageCluster> copy;  ///< images: the mirrored members
        SourceGeometry geometry;           ///< its member tree's far fields, in this space
        const PatchMesh& mesh() const { return copy ? copy->mesh : realMesh; }
        const Cluster& cluster() const { return copy ? copy->cluster : real; }
        /// Sample patches of the real cluster as indices into mesh().
        ClusterSamples local(const ClusterSamples& samples) const {
            return copy ? copy->local(real, samples) : samples;
        }
    };
    Shooter shooter(const Source& s, size_t c) const;
    /// What a shooter sends patch→patch: per member position k its luminance (cd/m²),
    /// and for a cluster larger than one member group the far field of each node of its
    /// member tree (far_field.h), in the shooter's space (an image's: mirrored).
    struct Emission {
        const std::vector<V>& amount;
        std::vector<FarSource> far;  ///< per node of m_trees[c]; empty: every member on its own
    };
    Emission emission(const Shooter& from, size_t c, const std::vector<V>& amount) const;

    struct Light {
        V unshot{0.0}, total{0.0}, pendingReflected{0.0};
        /// Σ |Y(ΔL_i)| A_i / A_C: members' unshot light may differ in sign (overshooting,
        /// corrections), and the residual must not let them cancel.
        double absUnshot = 0;
        /// Σ ρ_i A_i / A_C over the members that have received light: the members that
        /// take an overshoot (an unlit member is taken to stay unlit). Set by pull().
        V litReflectance{0.0};
        int radius = 0;
    };

    /// False when the solve must stop without converging (stall, time cap); see step().
    bool progressing(double residual);
    /// A patch that has received light, direct or indirect, so far.
    bool isLit(size_t j) const { return lum(m_direct[j]) != 0 || lum(m_indirect[j]) != 0; }
    /// Stall detection (see step()): the smallest residual seen and the shots since.
    double m_bestResidual = 0;
    int64_t m_shotsSinceBest = 0;
    std::chrono::steady_clock::time_point m_start;

    V reflected(size_t j) const { return m_reflectance[j] * (m_direct[j] + m_indirect[j]) / kPi; }  // L = ρ E / π
    /// |ΔL_C + pending| A_C in cd: what a shot of cluster c ships (net over its members).
    double clusterPower(size_t c) const;
    /// (Σ |ΔL_i| A_i + |pending| A_C) in cd: cluster c's share of the residual.
    double clusterResidual(size_t c) const;
    int radiusFor(size_t c) const;
    void pushPull(size_t c);
    void pull(size_t c);
    /// What one call delivered to a receiver cluster's members: the flux Σ ΔE_j A_j (lm
    /// per channel) and its magnitude Σ |Y(ΔE_j)| A_j (lm; larger where deliveries of both
    /// signs meet, which overshooting ships). Summed as they are made, so that a shot's
    /// conservation needs no pass over the patches it reached.
    struct Delivery {
        V flux{0.0};
        double magnitude = 0;
    };
    /// A cluster→cluster shot: adds e · shape_k (see receiverShape), × visible[k] when
    /// given (memberVisibility), to this shot's pending illuminance of the receiver's
    /// members (m_shotPending).
    Delivery addPending(const Cluster& source, size_t receiver, const V& e,
                        const std::vector<double>* visible = nullptr);
    void receive(size_t j, const V& deltaE);
    /// Patch→patch from cluster c of source s (as `from` shows it) to the receiver's
    /// patches: adds ΔE_j to into[j]. `terms` counts the source terms evaluated (members
    /// and far nodes, per receiver patch).
    Delivery shootPatches(const Source& s, const Shooter& from, size_t c, const Emission& light, size_t receiver,
                          std::vector<V>& into, int64_t& terms);
    /// Flux a shot delivered, counted where it left the shooter (through mirrors:
    /// delivered / Π Ks), lm: signed, and its magnitude — per patch (Delivery) when the
    /// scene has no mirrors, so the conservation below is exact; through mirrors per
    /// receiver and source — and what the mirrors absorbed of it (lm, before the
    /// conservation's adjustment).
    struct AtSource {
        bool throughMirrors = false;  ///< the scene has mirror images (more than one source)
        double net = 0, magnitude = 0, mirrorLoss = 0;
        /// Books a delivery to one receiver from source s.
        void add(const Source& s, const Delivery& d) {
            const double atS = lum(atSource(d.flux, s.weight));
            net += atS;
            magnitude += throughMirrors ? std::abs(atS) : d.magnitude;
            if (s.image) mirrorLoss += lum(radiosity::mirrorLoss(d.flux, s.weight));
        }
        /// Books what another account holds (one receiver's deliveries).
        void add(const AtSource& other) {
            net += other.net;
            magnitude += other.magnitude;
            mirrorLoss += other.mirrorLoss;
        }
    };
    /// One shot of cluster c: what its passes share.
    struct Shot {
        size_t c = 0;
        int r = 0;                                     ///< r_v in voxels: receivers nearer take patch→patch
        std::vector<std::optional<Shooter>> shooters;  ///< per source; none where nothing of c passes its chain
        std::vector<std::vector<char>> corrected;      ///< [source][receiver]: got the source's total in a correction
        std::vector<V> overshoot;                      ///< per member: what it ships beyond its unshot light
        std::vector<V> unshot;                         ///< per member: the light that leaves, cd/m²
        std::vector<double> unshotPower;               ///< per member ΔL_i A_i: where the rays leave from
        V deltaLC{0.0};                                ///< ΔL_C, cd/m²
        double shotFlux = 0;                           ///< lm
        std::vector<ClusterSamples> localSamples;      ///< per source: the ray samples in its shooter's mesh
        std::vector<std::vector<char>> regionOpen;     ///< images: the voxel regions light reaches through the chain
        std::vector<AtSource> bookedAt;                ///< per receiver: its deliveries, booked at their source
        std::vector<char> isNear;                      ///< [source · n + receiver]: patch→patch
        std::vector<char> nearAny;                     ///< per receiver: patch→patch from some source
    };
    /// With overshooting, what each member of C ships beyond its unshot light, ρ_i E_amb / π.
    std::vector<V> overshootOf(const Cluster& C) const;
    /// The shooter's unshot light (plus the overshoot) leaves: fills shot.unshot,
    /// unshotPower, deltaLC and shotFlux; the members keep minus the overshoot.
    void releaseUnshot(Shot& shot);
    /// Each source's ray samples and, for images, the voxel regions its chain lets light reach.
    void prepareSources(Shot& shot, const ClusterSamples& samples) const;
    /// Cluster→cluster to every receiver beyond r_v; marks the nearer ones for patch→patch.
    void shootClusterToCluster(Shot& shot);
    /// Patch→patch to the receivers shootClusterToCluster marked, with each source's emission.
    void shootPatchToPatch(Shot& shot);
    /// Receives this shot's collected deliveries (m_shotE, m_shotPending), adjusted to
    /// the flux shot when conserving. `redelivered`: the flux (lm, at the source) this
    /// shot's corrections took away to deliver again; `delivered`: the shot's deliveries
    /// at the source.
    void deliver(double shotFlux, double redelivered, const AtSource& delivered);
    /// A shot whose flux or deliveries are not finite stops the solve at once, with what
    /// is known of the shooter and the first receiver hit (InternalError): a solution
    /// holding NaN is refused at the end anyway, after the whole solve's time.
    void checkFinite(size_t c, double shotFlux, double redelivered, const AtSource& delivered) const;
    /// E_amb in lx: the illuminance the unshot power will still add everywhere (overshooting).
    V ambientIlluminance() const;
    /// What a correction moved, lm per channel: the history taken away, and the flux
    /// delivered patch→patch in its place.
    struct Correction {
        V removed{0.0};
        Delivery delivered;
    };
    Correction correct(const Source& s, const Shooter& from, size_t c, size_t d, const ClusterSamples& shotSamples,
                       const SourceLight& shipped, const Emission& totalOfSource);  // energy_correction.cpp
    /// Shooter c's radius r_v grew to r: corrects every receiver in the ring between the
    /// old and the new radius (correct()), for each source `shooters` holds, marks them in
    /// corrected[source][receiver] and books their deliveries in `delivered`. Returns the
    /// flux (lm, at the source) the corrections took away, to be delivered again.
    /// `overshoot`: what each member ships beyond its unshot light this shot.
    double correctRing(size_t c, int r, const std::vector<V>& overshoot,
                       const std::vector<std::optional<Shooter>>& shooters, std::vector<std::vector<char>>& corrected,
                       AtSource& delivered);  // energy_correction.cpp
    bool coplanar(const Cluster& a, const Cluster& b) const;
    /// False when no light of cluster c (as source s shows it: Cs) can pass through s's
    /// mirrors to cluster d: c lies behind the chain's first mirror, d behind its last,
    /// or no segment between their bounding balls crosses the chain's mirror polygons.
    bool canReach(const Source& s, const Cluster& Cs, size_t c, size_t d) const {
        if (!s.image) return true;
        const Cluster& D = m_clustering.clusters[d];
        return s.sends[c] && s.receives[d] &&
               s.image->mayPass(Cs.centroid, 0.5 * Cs.diameter, D.centroid, 0.5 * D.diameter);
    }
    /// Image voxels are the mirrored centroids' cells on the real grid, which the mirror
    /// plane need not be aligned with: a receiver touching an image across the mirror can
    /// be one voxel away. Image distances count one voxel less, so touching clusters
    /// exchange patch→patch (cluster→cluster there put a point source beside the receiver).
    static int imageMargin(const Source& s) { return s.image ? 1 : 0; }
    /// Whether receiver cluster d is in the near field (patch→patch) of shooter c (as
    /// source s shows it, Cs) at voxel radius r: within r voxels (an image one voxel
    /// nearer, imageMargin), or touching it in the real scene (touchingClusters: along a
    /// seam or a contact line the form factor is singular, whatever r). A correction ring
    /// is what is near at the new radius and was not at the old.
    bool inNearField(const Source& s, const Cluster& Cs, size_t c, size_t d, int r) const {
        if (m_clustering.voxelDistance(Cs, m_clustering.clusters[d]) - imageMargin(s) < r) return true;
        return !s.image && !m_touching.empty() && std::binary_search(m_touching[c].begin(), m_touching[c].end(), d);
    }

    const scene::Scene& m_scene;
    const PatchMesh& m_mesh;
    const Clustering& m_clustering;
    const Visibility& m_vis;
    scene::ShootingOptions m_options;  ///< overshoot is switched off when the residual stalls
    double m_analyticDistance;         ///< scene.formFactors.analyticDistance
    bool m_mirrorImages;               ///< scene.mirrorImages: the image method on
    scene::ClusterOptions m_clusterOptions;
    double m_maxStep = 0;
    std::vector<V> m_reflectance, m_direct, m_indirect, m_unshot, m_pending;
    std::vector<double> m_patchArea;  ///< m², per patch: the per-shot loops read it apart from the Patch records
    std::vector<Light> m_light;
    std::vector<std::unique_ptr<MirrorView>> m_mirrorViews;
    std::vector<Source> m_sources;  ///< the real scene first, then one per image
    /// Per patch, this shot's deliveries in lx before they are received: patch→patch
    /// (m_shotE) and cluster→cluster (m_shotPending, joins m_pending).
    std::vector<V> m_shotE, m_shotPending;
    /// Per cluster: which of m_shotE (kReachedPatches) and m_shotPending (kReachedPending)
    /// hold a delivery for some member, so deliver() visits only the clusters a shot
    /// reached, and reads only the arrays that hold something for them.
    std::vector<char> m_reached;
    static constexpr char kReachedPatches = 1, kReachedPending = 2;
    /// The occupied voxels (clusters.h): a shot through a mirror tests these first.
    VoxelRegions m_regions;
    std::vector<std::vector<uint32_t>> m_touching;  ///< per cluster, the clusters it touches (sorted)
    /// Per cluster, its member tree (member_tree.h) in real space; its leaves are the
    /// member groups that share a visibility ray; an image's tree is the same members,
    /// their centroids mirrored.
    std::vector<MemberTree> m_trees;
    bool m_conserve = false;
    bool m_finished = false;          ///< finish() has run: the per-patch arrays are gone
    double m_finishedUnshotFlux = 0;  ///< lm, unshotFlux() when finish() ran
    /// The mirrors' back faces (vertices reversed, normal −n): light shot into them is
    /// absorbed (a mirror's back is not a patch).
    std::vector<std::vector<Vec3>> m_mirrorBacks;
    /// Flux (lm) the members of cluster c send into mirror backs, unoccluded form factors.
    double intoMirrorBacks(const Cluster& C, const std::vector<double>& unshotPower) const;
    bool m_mirrorChainsTruncated = false;  ///< some light reflected beyond the chains is not modelled
    V m_meanReflectance{0.0};              ///< area-weighted ρ̄
    double m_area = 0;                     ///< Σ A_i, m²
    V m_signedUnshot{0.0};                 ///< Σ_C (ΔL_C + pending) A_C in cd, signed; set by step()
    double m_shotSincePushPull = 0;
    double m_powerAtPushPull = 0;
    ShootingStatistics m_stats;
};

}  // namespace rayrad::radiosity
