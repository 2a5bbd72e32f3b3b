#include <radiosity/display/seam_profile_gathers.h>

#include <radiosity/gather/gather.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <tuple>

namespace rayrad::radiosity {

namespace {
/// Near triangles split toward the point as deep as for the seam vertices (edge_vertices.cpp).
constexpr int kMaxSplitDepth = 12;

/// A profile whose first node's |δ| is below this many kSeamProfileTolerance of the light
/// takes no second round. The second round moves the first node by under a quarter of
/// its value in 90 % of the bench hall's profiles (median 4 %), so what it would change
/// there is within the tolerance; in the hall 6 060 of 13 002 profiles skip it, their
/// change at the 99th percentile 0.48 % of the light.
constexpr double kSecondRoundShare = 4.0;

double nodeTau(int k) {
    return SeamProfiles::nodeTau(k);
}

/// An edge from a seam vertex to one off the seams, with a patch it bounds.
struct Candidate {
    uint32_t from, to;
    size_t patch;
};

/// The edges at least `minEdge` m long from one of `seamVertices` to a vertex that is not
/// one, sorted by (from, to), each once.
std::vector<Candidate> profileEdges(const PatchMesh& mesh, const std::vector<uint32_t>& seamVertices,
                                    const std::vector<uint32_t>& unprofiled, double minEdge) {
    // The edges from a seam vertex to one off the seams, each with a patch it bounds.
    std::vector<char> seam(mesh.vertices.size(), 0), from(mesh.vertices.size(), 0);
    for (uint32_t v : seamVertices) seam[v] = 1, from[v] = 1;
    for (uint32_t v : unprofiled) from[v] = 0;
    std::vector<Candidate> candidates;
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        if (mesh.isCovered(i)) continue;
        const auto& v = mesh.patches[i].v;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                if (a != b && from[v[a]] && !seam[v[b]] &&
                    glm::length(mesh.vertices[v[b]] - mesh.vertices[v[a]]) >= minEdge)
                    candidates.push_back({v[a], v[b], i});
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        return std::tie(x.from, x.to, x.patch) < std::tie(y.from, y.to, y.patch);
    });
    candidates.erase(
        std::unique(candidates.begin(), candidates.end(),
                    [](const Candidate& x, const Candidate& y) { return x.from == y.from && x.to == y.to; }),
        candidates.end());
    return candidates;
}
}  // namespace

SeamProfiles gatherSeamProfiles(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                                const RadiositySolution& solution, const Visibility& vis,
                                const std::vector<uint32_t>& seamVertices, const std::vector<uint32_t>& unprofiled,
                                double minEdge, int levels, size_t* gathers,
                                const std::function<void(double)>& onProgress) {
    levels = std::clamp(levels, 0, SeamProfiles::kNodes);
    if (levels == 0 || seamVertices.empty() || solution.vertexIndirect.empty()) return {};
    const std::vector<Candidate> candidates = profileEdges(mesh, seamVertices, unprofiled, minEdge);

    GatherOptions options = GatherOptions::plain();  // near parts only: the far field's settings do not enter
    options.maxSplitDepth = kMaxSplitDepth;
    Gatherer gatherer(scene, mesh, clustering, solution, vis, options);
    Gatherer::CornerSource corners = [&](size_t patch, int corner, double /*share*/) {
        return solution.vertexIndirect[mesh.patches[patch].v[corner]];
    };
    const double nudge = pointNudge(scene);
    std::atomic<size_t> done{0}, taken{0};
    const double total = 2.0 * static_cast<double>(candidates.size());
    // δ at a node comes from the near patches alone: with N the patches near the edge (one
    // set for all its points), E = near_N + rest_N at every point, and rest_N — light from
    // at least two patch diameters away — is linear along the edge to second order, so
    //   δ(x) = near_N(x) − ((1 − τ) near_N(s) + τ near_N(t))
    // (the seam vertex s is gathered; an error of the reconstruction at t is left as the
    // rest of the mesh shows it). A near part costs a fraction of a whole gather.
    // Two rounds. The first takes the near patches linear between their corners: beside a
    // seam those are the other wall's triangles, whose own band then reads low. The second
    // refines them toward the point with the first round's display values at their
    // midpoints (the gather's graded refinement, fed with display values, not gathers), at
    // the first round's nodes.
    using Part = Gatherer::Part;
    std::vector<int> nodes(candidates.size(), 0);
    std::vector<char> firstRoundOnly(candidates.size(), 0);  // the first node below kSecondRoundShare tolerances
    std::vector<std::vector<uint32_t>> nearSets(candidates.size());  // each edge's near patches, for both rounds
    SeamProfiles profiles;
    for (int round = 0; round < 2; ++round) {
        const SeamProfiles& before = profiles;
        Gatherer::MidpointSource display = [&](size_t patch, uint64_t a, uint64_t b, const Vec3& y, double /*share*/) {
            const Patch& p = mesh.patches[patch];
            const Vec3 w = barycentric(mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2), y);
            const Rgb linear = weightedVertexIndirect(mesh, solution, patch, {w[0], w[1], w[2]});
            // Any id the refinement can hand back: this source keeps no memo.
            return Gatherer::Midpoint{(uint64_t(1) << 63) | ((std::min(a, b) << 24) ^ std::max(a, b)),
                                      glm::max(linear + before.deltaAt(patch, w[1], w[2]), Rgb(0.0))};
        };
        std::vector<SeamProfiles::Edge> edges(candidates.size());
        tbb::parallel_for(size_t(0), candidates.size(), [&](size_t c) {
            const Candidate& e = candidates[c];
            const Vec3 s = mesh.vertices[e.from], t = mesh.vertices[e.to];
            const Rgb Es = solution.vertexIndirect[e.from], Et = solution.vertexIndirect[e.to];
            const Vec3 n = mesh.patches[e.patch].normal;
            if (round == 0) nearSets[c] = gatherer.nearPatches({s, t});
            const std::vector<uint32_t>& nearEdge = nearSets[c];
            auto nearAt = [&](const Vec3& y) {
                ++taken;
                Gatherer::Request near(nudgeInside(mesh, e.patch, y, nudge), n, &corners, Gatherer::Threads::Serial);
                near.midpoints = round > 0 ? &display : nullptr;
                near.part = Part::Near;
                near.nearSet = &nearEdge;
                return gatherer.gatherWith(near);
            };
            // A profile whose first node was small is not worth a second round (the other
            // wall's band changes it by a fraction of that: kSecondRoundShare).
            if (round > 0 && firstRoundOnly[c]) {
                edges[c] = before.edges()[c];  // the same order: both sorted by (from, to)
                ++done;
                return;
            }
            const Rgb nearS = nearAt(s), nearT = nearAt(t);
            SeamProfiles::Edge out;
            out.from = e.from, out.to = e.to;
            const int last = round == 0 ? levels : nodes[c];
            int k = 0;
            for (; k < last; ++k) {
                const double tau = nodeTau(k);
                const Rgb delta = nearAt(s + tau * (t - s)) - ((1 - tau) * nearS + tau * nearT);
                out.delta[k] = RgbF(delta);
                const double shown = luminance((1 - tau) * Es + tau * Et);
                const double light = std::abs(shown + luminance(delta));
                if (round == 0 && k == 0)
                    firstRoundOnly[c] = std::abs(luminance(delta)) < kSecondRoundShare * kSeamProfileTolerance * light;
                if (round == 0 && std::abs(luminance(delta)) < kSeamProfileTolerance * light) {
                    ++k;
                    break;
                }
            }
            if (round == 0) nodes[c] = k;
            // Below the last node gathered, straight to 0 at the seam.
            for (int j = k; j < SeamProfiles::kNodes; ++j)
                out.delta[j] = out.delta[k - 1] * static_cast<float>(nodeTau(j) / nodeTau(k - 1));
            edges[c] = out;
            if (round > 0 || firstRoundOnly[c]) std::vector<uint32_t>().swap(nearSets[c]);  // not needed again
            size_t n2 = ++done;
            if (onProgress && n2 % 16 == 0) onProgress(static_cast<double>(n2) / total);
        });
        // The last round's per-patch index goes before the next one is built.
        profiles = SeamProfiles(seamVertices, std::move(edges));
        profiles.index(mesh);
    }
    if (gathers) *gathers = taken;
    return profiles;
}

}  // namespace rayrad::radiosity
