// Which member-tree leaves cannot light a point: all of them behind the point's tangent
// plane, or the point behind all of their planes. The gather skips them without visiting
// their patches (whose form factors would each come out 0).
#pragma once

#include <core/math.h>
#include <radiosity/clusters.h>
#include <radiosity/member_tree.h>
#include <radiosity/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// A node's members' normals lie within `halfAngle` of `axis` (a normal cone); their
/// corners within the node's sphere (MemberNode: centroid, diameter / 2).
struct NormalCone {
    Vec3 axis{0.0};         ///< unit; 0 when the normals spread too far for a cone
    double cosHalf = -1;    ///< cos of the half-angle
    double sinHalf = 0;     ///< sin of the half-angle
};

/// The normal cone of every node of `tree` (indexed like tree.nodes).
std::vector<NormalCone> normalCones(const PatchMesh& mesh, const Cluster& cluster, const MemberTree& tree);

/// True when no member of `node` can send light to x (unit normal n): each member's form
/// factor to x is 0, by the exits of formFactorToPolygon and formFactorPointApprox. Either
/// every corner lies behind x's tangent plane, (c − x)·n + r < 0, or x lies behind every
/// member's plane: for each member j, (x − c_j)·N_j ≤ max over the cone of (x − c)·N + r
/// = (x − c)·A cos α + |(x − c) × A| sin α + r < 0 (c, r the node's sphere, A, α its cone).
/// Conservative by a margin far above double rounding, so a member it skips is one whose
/// form factor would have been exactly 0.
bool bringsNothing(const MemberNode& node, const NormalCone& cone, const Vec3& x, const Vec3& n);

}  // namespace rayrad::radiosity
