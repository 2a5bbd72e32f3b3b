// Far field: a node of a cluster's member tree seen from far away as one source (a
// Barnes–Hut far field). Used by the final gather (the solution's reflected light) and by
// the shooting's patch→patch near field (a shot's unshot light).
#pragma once

#include <radiosity/clusters/member_tree.h>
#include <radiosity/mirrors/mirror_images.h>

#include <glm/mat3x3.hpp>

#include <array>
#include <vector>

namespace rayrad::radiosity {

/// A node's light moments up to the second, for E ≈ W g(at) + ½ tr(H_g M) with
/// g = cosθ_x cosθ_y / r². Built from |L|: `sign` is −1 when the node's light is negative
/// (an overshooting shot takes light back), and a node whose members' light has both signs
/// has no far field (`mixed`: open it).
/// The expansion's coefficients are summed in double and kept in float (one per member
/// tree node, a third of the patches: 144 bytes each instead of 248); the expansion's own
/// error at three diameters is far above float rounding.
struct FarSource {
    Vec3 at{0.0};                     ///< luminance-weighted centroid, m
    double reach = 0;                 ///< twice the largest distance from `at` to a member corner, m
    std::array<glm::vec3, 3> flux{};  ///< per channel Φ = Σ L_j A_j n_j (cd)
    glm::vec3 normal{0.0f};           ///< Φ's direction (luminance), unit
    glm::vec3 share{0.0f};            ///< per channel Σ L_j A_j over the luminance sum W
    glm::mat3 moment{0.0f};           ///< M = Σ Y(L_j) ∫_{A_j} (y − at)(y − at)ᵀ dA (cd m²)
    /// P = Σ Y(L_j) A_j (c_j − at) n_jᵀ (cd m): how the normals turn across a curved node
    /// (0 for a flat one). Its term −tr(J P), J the Jacobian of (n·u) u / |u|⁴, is of the
    /// same order as the moment's; without it a curved node lost light (a closed sphere's
    /// solve at 20° normal tolerance: 0.6 % of the indirect light).
    glm::mat3 turning{0.0f};
    /// Where the node's visibility is sampled (visibility_share.h; only with
    /// FarRayTargets::PowerSamples): member positions k stratified by power, sample i
    /// where the running sum of the members' |Y(L_j)| A_j in tree order (which keeps them
    /// spread in space) reaches (i + ½)/4 of it.
    std::array<uint32_t, 4> rayTo{};
    float sign = 1;      ///< +1, or −1 for a node of negative light
    bool mixed = false;  ///< members of both signs: no far field
};

/// Φ of the luminance, Σ Y(L_j) A_j n_j (cd): each component Y of the three channels'
/// fluxes' components.
Vec3 luminanceFlux(const Vec3& red, const Vec3& green, const Vec3& blue);

/// Which ray targets a far source needs: none (its geometry only), or its power-stratified
/// visibility samples FarSource::rayTo (the final gather, visibility_share.h, and the
/// shooting's patch→patch near field).
enum class FarRayTargets { None, PowerSamples };

/// The far sources of every node of `tree` (indexed like tree.nodes). `luminance[k]` is
/// the luminance (cd/m², RGB) of member position k of `cluster` (its order in
/// Cluster::patches); `mesh` holds the cluster's patches.
std::vector<FarSource> farSources(const PatchMesh& mesh, const Cluster& cluster, const MemberTree& tree,
                                  const std::vector<Rgb>& luminance, FarRayTargets targets);

/// The node's light at x with normal n (lx, RGB): g expanded about its luminance-weighted
/// centroid to second order, E ≈ cosθ_x (−Φ·u)/r³ + ½ tr(H_g M) − tr(J P) (the
/// first-order term in position vanishes there; P carries the first order in the normals);
/// nothing when the node faces away. `image` (or null) mirrors the node.
Rgb farField(const FarSource& f, const Vec3& x, const Vec3& n, const MirrorImage* image);

}  // namespace rayrad::radiosity
