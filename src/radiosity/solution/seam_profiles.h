// Display values graded toward concave seams: along each mesh edge that leaves a seam
// vertex, the indirect light gathered at 1/2, 1/4 … of the edge, so the ray tracer follows
// the fall-off into a room's edges that linear interpolation between vertices misses.
#pragma once

#include <core/math.h>
#include <radiosity/mesh/patch_mesh.h>
#include <scene/settings.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// Near a concave seam the indirect light rises like d·ln(1/d) with the distance d from the
/// seam (the neighbouring wall's luminance rises linearly from the seam, and the form
/// factor of a strip at grazing angles weighs it by ln): its slope is infinite at the seam,
/// and a triangle interpolated linearly from its corners reads up to 10 % low over the band
/// of triangles touching the seam (the Cornell box's ceiling beside the back wall,
/// bench/seam_profile.py). Halving the triangles narrows the band but hardly lowers it.
///
/// So each edge of the mesh from a seam vertex s to a vertex t off the seams carries a
/// profile: δ(τ) = E_gathered(s + τ (t − s)) − E_linear(s + τ (t − s)) (lx, RGB) at the
/// nodes τ_k = 2^−k, k = 1 … kNodes — a mesh graded geometrically toward the seam, its
/// vertices gathered — piecewise linear between them, 0 at τ = 0 (s is gathered already)
/// and at τ = 1. Inside a triangle the edge profiles are blended so that on every edge the
/// value is that edge's profile, the same from both of its triangles (no crack):
///   one seam corner s, others t, u:   δ = (λ_t P_st(1 − λ_s) + λ_u P_su(1 − λ_s)) / (λ_t + λ_u)
///   two seam corners s, r, other t:   δ = (λ_s P_st(λ_t) + λ_r P_rt(λ_t)) / (λ_s + λ_r)
/// (λ barycentric); no correction in triangles with no seam corner or only seam corners.
/// An edge whose profile was not gathered (too short) counts as δ = 0, which keeps every
/// edge continuous too. Each group part of a solve has its own profiles; they add.
class SeamProfiles {
  public:
    /// τ = 1/2, 1/4, 1/8, 1/16, 1/32: the most radiosity.seam_profile_nodes allows.
    static constexpr int kNodes = scene::ReconstructionOptions::kMaxSeamProfileNodes;
    /// τ_k = 2^−(k+1) of node k = 0 … kNodes − 1.
    static double nodeTau(int k) { return std::ldexp(1.0, -(k + 1)); }
    /// The correction along the edge from seam vertex `from` to vertex `to`: δ at τ_k (lx).
    struct Edge {
        uint32_t from = 0, to = 0;
        std::array<RgbF, kNodes> delta{};
    };

    bool empty() const { return m_edges.empty(); }
    size_t edgeCount() const { return m_edges.size(); }
    const std::vector<uint32_t>& seamVertices() const { return m_seams; }
    const std::vector<Edge>& edges() const { return m_edges; }

    /// From parts (sorted or not; duplicates of an edge add). Call index() before deltaAt.
    SeamProfiles(std::vector<uint32_t> seamVertices, std::vector<Edge> edges);
    SeamProfiles() = default;
    /// this += scale · other, edge by edge (a light group's part of a dimmed solution).
    void add(const SeamProfiles& other, double scale);

    /// Builds the per-patch lookup deltaAt uses (after construction, loading or add).
    void index(const PatchMesh& mesh);
    /// δ (lx, RGB) at barycentric (u, v) of patch p (corners weighted 1−u−v, u, v).
    Rgb deltaAt(size_t patch, double u, double v) const;

  private:
    /// A patch's corners that carry profiles: `kind` 1 (corner s a seam, t and u not) or
    /// 2 (s and r seams, t not), corner indices 0–2, and the profiles (−1: not gathered).
    struct PatchProfiles {
        int8_t kind = 0;
        std::array<int8_t, 3> corner{};          ///< kind 1: s, t, u; kind 2: s, r, t
        std::array<int32_t, 2> profile{-1, -1};  ///< kind 1: s→t, s→u; kind 2: s→t, r→t
    };
    /// δ along edge `e` at τ ∈ [0, 1].
    Rgb profileAt(int32_t e, double tau) const;

    std::vector<uint32_t> m_seams;      ///< sorted, unique
    std::vector<Edge> m_edges;          ///< sorted by (from, to), unique
    std::vector<int32_t> m_patchIndex;  ///< per patch: into m_patches, −1 none (empty before index())
    std::vector<PatchProfiles> m_patches;
};

}  // namespace rayrad::radiosity
