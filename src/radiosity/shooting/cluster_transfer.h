// Cluster→cluster transfer: the illuminance a receiver cluster gets per unit source luminance.
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/clusters/far_field.h>
#include <radiosity/clusters/member_tree.h>
#include <radiosity/mesh/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// A source cluster's member tree with each node's far field at unit luminance
/// (far_field.h), in the source's own space (an image's: mirrored), so the sum of its
/// members' form factors seen from a point is taken node by node: a node farther than
/// `farDiameters` of its reach counts as one unless x's horizon cuts through it, other
/// nodes are opened down to the members.
struct SourceGeometry {
    const MemberTree* tree = nullptr;
    std::vector<FarSource> unitFar;  ///< per node of *tree
    double farDiameters = 0;
};
/// The geometry of `source` (member positions as in `tree`) for `farDiameters` > 0; with
/// 0, or a tree of one node, none (every member on its own).
SourceGeometry sourceGeometry(const PatchMesh& mesh, const Cluster& source, const MemberTree& tree,
                              double farDiameters);

/// How a source's light is spread over its members, for the transfers that take the
/// source as one: each member's luminance relative to the cluster's mean (by area),
/// member[k] for member position k (Cluster::patches), node[i] for node i of its member
/// tree (the area-weighted mean of its members'). Empty: uniform, as the paper's
/// cluster→cluster transfer takes it. A floor cluster in front of McGuire's short block,
/// brighter away from the block than beside it, shot its face 5 % more as uniform than
/// its members send.
struct SourceLight {
    std::vector<double> member, node;
};
/// The relative light of `source` from its members' luminances (Y, cd/m², by member
/// position); uniform (empty) when their mean is not positive or one is negative (an
/// overshooting shot's members may take light back): relative values then mean nothing.
SourceLight sourceLight(const PatchMesh& mesh, const Cluster& source, const MemberTree& tree,
                        const std::vector<double>& luminance);

/// Σ_i w_i F(dA_x → A_i) over the source's members, at x with unit normal n, w_i their
/// relative light (`light`; 1 without): each member analytic within `analyticDistance`
/// of its diameters, else the point approximation; with `geometry` (its tree and far
/// fields), far nodes of the member tree as one source, weighted by the node's light.
double memberFormFactorSum(const PatchMesh& sourceMesh, const Cluster& source, const SourceGeometry* geometry,
                           const SourceLight* light, const Vec3& x, const Vec3& n, double analyticDistance);

/// What clusterTransfer found of a pair whose sample rays disagreed (a shadow's edge
/// crossing it): then memberVisibility says which of the receiver's members are lit.
struct SplitTransfer {
    bool partial = false;  ///< some sample rays were blocked and some were not
    double open = 0;       ///< π F without V, lx per cd/m²
};

/// π F(dA_D → C) · V(C, D) in lx per cd/m²: the illuminance at the receiver cluster's
/// centroid (with its mean normal) from the source cluster at unit luminance.
/// Adaptive accuracy instead of a deeper hierarchy: far away (beyond 4 source
/// diameters) the point approximation A_C cosθ_C cosθ_D / (π r²); nearer, the sum of the
/// member patches' form factors (memberFormFactorSum, through `geometry` when given),
/// each weighted by its share of the source's light (`light`, when given).
/// Nearer, with `receiverDetail` (receiverShape shares the light by the point kernel g),
/// that sum is taken where the receiver's surface is: at its sample patches, with their
/// own normals, and carried to the centroid by g, F_c = g_ref Σ_s A_s F_s / Σ_s A_s g_s
/// (g_ref: what receiverShape divides by, g at the centroid in all but degenerate cases).
/// The sum at the centroid with the mean normal lost light on curved receivers, whose
/// centroid lies off their surface: a closed sphere's solve at 20° normal tolerance
/// left −0.31 % of its light unaccounted; with the samples +0.025 % (no clusters: +0.08 %).
/// V is the visible fraction of up to four rays from `sourceSamples` (member patches of
/// the source, see powerSamples) to the receiver's sample patches, counting only the
/// pairs that face each other when any does: on a curved cluster a sample facing away
/// from the other end sent its ray through its own object (balls standing on a floor,
/// 20°, came out 0.97 % dark with the sampled F alone; +0.17 % with the facing pairs).
/// The source may be a mirror image (its own mesh, and a MirrorPath as `vis`).
/// A pair with F < 10⁻³ (most pairs of a furnished room) takes V from the first (facing)
/// sample pair alone: a wrong V there costs at most a thousandth of the source's luminance. The
/// rule depends on geometry only, so the energy correction reconstructs what earlier
/// shots delivered with the same rays.
/// `split` (if given) says whether the sample rays disagreed, and gets π F without V.
double clusterTransfer(const PatchMesh& sourceMesh, const Cluster& source, const ClusterSamples& sourceSamples,
                       const PatchMesh& receiverMesh, const Cluster& receiver, const Visibility& vis,
                       double analyticDistance, bool receiverDetail, const SourceGeometry* geometry = nullptr,
                       const SourceLight* light = nullptr, SplitTransfer* split = nullptr);

/// For a pair whose sample rays disagreed: visible[k], the fraction of two rays from the
/// receiver's member k to the source's sample patches it faces (the pair (k, k+1) of
/// them in turn) that arrive; 0 for a member facing none. A ball standing on a floor
/// shadows part of a floor cluster; the cluster's single V spread that shadow evenly
/// over its members (the floor beside the balls 10 % L2 from the unclustered solve).
/// One ray per member left bands on the hall's desk fronts (a member's V all or nothing
/// from one point of a large source); four gave the hall the same error as two, at more
/// rays (see docs/validation.md).
void memberVisibility(const PatchMesh& sourceMesh, const ClusterSamples& sourceSamples, const PatchMesh& receiverMesh,
                      const Cluster& receiver, const Visibility& vis, std::vector<double>& visible);

/// How a cluster→cluster shot from `source` is shared among the receiver's patches:
/// shape[k] multiplies the illuminance computed at the receiver's centroid for member k.
/// `detail` false: all 1 (uniform push-down, the paper's eq. 2). true: the ratio of the
/// point kernel cosθ_k cosθ_C / r_k² at member k to its value at the centroid, so each
/// patch gets its own orientation and distance (patches along an edge see far sources
/// at grazing angles) and curved clusters receive their projected area, not A_D.
void receiverShape(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, bool detail,
                   std::vector<double>& shape);

}  // namespace rayrad::radiosity
