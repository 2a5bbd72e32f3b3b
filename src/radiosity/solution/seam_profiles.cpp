#include <radiosity/solution/seam_profiles.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace rayrad::radiosity {

namespace {
bool edgeLess(const SeamProfiles::Edge& a, const SeamProfiles::Edge& b) {
    return std::tie(a.from, a.to) < std::tie(b.from, b.to);
}
}  // namespace

SeamProfiles::SeamProfiles(std::vector<uint32_t> seamVertices, std::vector<Edge> edges)
    : m_seams(std::move(seamVertices)) {
    std::sort(m_seams.begin(), m_seams.end());
    m_seams.erase(std::unique(m_seams.begin(), m_seams.end()), m_seams.end());
    std::sort(edges.begin(), edges.end(), edgeLess);
    for (const Edge& e : edges) {
        if (!m_edges.empty() && m_edges.back().from == e.from && m_edges.back().to == e.to) {
            for (int k = 0; k < kNodes; ++k) m_edges.back().delta[k] += e.delta[k];
        } else {
            m_edges.push_back(e);
        }
    }
}

void SeamProfiles::add(const SeamProfiles& other, double scale) {
    std::vector<uint32_t> seams = m_seams;
    seams.insert(seams.end(), other.m_seams.begin(), other.m_seams.end());
    std::vector<Edge> edges = m_edges;
    for (Edge e : other.m_edges) {
        for (auto& d : e.delta) d *= static_cast<float>(scale);
        edges.push_back(e);
    }
    *this = SeamProfiles(std::move(seams), std::move(edges));
}

void SeamProfiles::index(const PatchMesh& mesh) {
    m_patchIndex.clear();
    m_patches.clear();
    if (m_edges.empty()) return;
    auto isSeam = [&](uint32_t v) { return std::binary_search(m_seams.begin(), m_seams.end(), v); };
    auto find = [&](uint32_t from, uint32_t to) -> int32_t {
        Edge key;
        key.from = from, key.to = to;
        auto it = std::lower_bound(m_edges.begin(), m_edges.end(), key, edgeLess);
        return it != m_edges.end() && it->from == from && it->to == to ? static_cast<int32_t>(it - m_edges.begin())
                                                                       : -1;
    };
    m_patchIndex.assign(mesh.patches.size(), -1);
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        const auto& v = mesh.patches[i].v;
        std::array<bool, 3> seam{isSeam(v[0]), isSeam(v[1]), isSeam(v[2])};
        const int count = int(seam[0]) + int(seam[1]) + int(seam[2]);
        if (count == 0 || count == 3) continue;
        PatchProfiles p;
        p.kind = static_cast<int8_t>(count);
        // The odd corner out first: the seam corner of kind 1, the other corner of kind 2.
        const int odd = count == 1 ? (seam[0] ? 0 : seam[1] ? 1 : 2) : (!seam[0] ? 0 : !seam[1] ? 1 : 2);
        const int a = (odd + 1) % 3, b = (odd + 2) % 3;
        if (count == 1) {  // s, t, u
            p.corner = {static_cast<int8_t>(odd), static_cast<int8_t>(a), static_cast<int8_t>(b)};
            p.profile = {find(v[odd], v[a]), find(v[odd], v[b])};
        } else {  // s, r, t
            p.corner = {static_cast<int8_t>(a), static_cast<int8_t>(b), static_cast<int8_t>(odd)};
            p.profile = {find(v[a], v[odd]), find(v[b], v[odd])};
        }
        if (p.profile[0] < 0 && p.profile[1] < 0) continue;
        m_patchIndex[i] = static_cast<int32_t>(m_patches.size());
        m_patches.push_back(p);
    }
}

Rgb SeamProfiles::profileAt(int32_t e, double tau) const {
    if (e < 0 || tau <= 0 || tau >= 1) return Rgb(0.0);
    const auto& d = m_edges[e].delta;
    if (tau >= nodeTau(0)) return Rgb(d[0]) * ((1 - tau) / (1 - nodeTau(0)));  // 0 at τ = 1
    for (int k = 0; k + 1 < kNodes; ++k) {
        const double hi = nodeTau(k), lo = nodeTau(k + 1);
        if (tau >= lo) {
            const double f = (tau - lo) / (hi - lo);
            return Rgb(d[k + 1]) * (1 - f) + Rgb(d[k]) * f;
        }
    }
    return Rgb(d[kNodes - 1]) * (tau / nodeTau(kNodes - 1));  // 0 at τ = 0
}

Rgb SeamProfiles::deltaAt(size_t patch, double u, double v) const {
    if (m_patchIndex.empty() || m_patchIndex[patch] < 0) return Rgb(0.0);
    const PatchProfiles& p = m_patches[m_patchIndex[patch]];
    const std::array<double, 3> lambda{1 - u - v, u, v};
    const double l0 = lambda[p.corner[0]], l1 = lambda[p.corner[1]], l2 = lambda[p.corner[2]];
    if (p.kind == 1) {  // s = corner 0; t, u = corners 1, 2; τ = 1 − λ_s along both edges
        const double sum = l1 + l2;
        if (sum <= 1e-12) return Rgb(0.0);
        return (l1 * profileAt(p.profile[0], sum) + l2 * profileAt(p.profile[1], sum)) / sum;
    }
    // s, r = corners 0, 1; t = corner 2; τ = λ_t along both edges
    const double sum = l0 + l1;
    if (sum <= 1e-12) return Rgb(0.0);
    return (l0 * profileAt(p.profile[0], l2) + l1 * profileAt(p.profile[1], l2)) / sum;
}

}  // namespace rayrad::radiosity
