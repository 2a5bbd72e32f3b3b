#include <radiosity/display/vertex_reconstruction.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace rayrad::radiosity {

namespace {

/// Samples a quadratic fit needs around a vertex (6 terms, with some to spare).
constexpr size_t kQuadraticSamples = 10;

/// Least-squares plane through (u, w, value) samples, value at (0, 0); false when the
/// sample positions are (nearly) collinear.
bool planeAtOrigin(const std::vector<Vec2>& uv, const std::vector<Rgb>& values, Rgb& out) {
    // Normal equations for [1 u w]·[a b c]ᵀ ≈ value.
    glm::dmat3 m(0.0);
    Rgb r1(0.0), ru(0.0), rw(0.0);
    for (size_t k = 0; k < uv.size(); ++k) {
        double u = uv[k].x, w = uv[k].y;
        m[0][0] += 1, m[1][0] += u, m[2][0] += w;
        m[0][1] += u, m[1][1] += u * u, m[2][1] += u * w;
        m[0][2] += w, m[1][2] += u * w, m[2][2] += w * w;
        r1 += values[k], ru += u * values[k], rw += w * values[k];
    }
    double scale = m[1][1] + m[2][2];
    if (uv.size() < 3 || std::abs(glm::determinant(m)) < 1e-9 * scale * scale * m[0][0]) return false;
    glm::dmat3 inv = glm::inverse(m);
    for (int ch = 0; ch < 3; ++ch) {
        glm::dvec3 rhs(r1[ch], ru[ch], rw[ch]);
        out[ch] = (inv * rhs)[0];  // a: the value at the vertex
    }
    return true;
}

/// Least-squares quadratic a + b u + c w + d u² + e uw + f w² through the samples, value at
/// (0, 0); false when there are fewer than kQuadraticSamples or they do not fix it.
bool quadraticAtOrigin(const std::vector<Vec2>& uv, const std::vector<Rgb>& values, Rgb& out) {
    constexpr int kTerms = 6;
    if (uv.size() < kQuadraticSamples) return false;
    // Scaled to the samples' spread, so the normal equations are well conditioned.
    double spread = 0;
    for (const Vec2& p : uv) spread = std::max(spread, glm::length(p));
    if (!(spread > 0)) return false;
    double m[kTerms][kTerms] = {}, rhs[3][kTerms] = {};
    for (size_t k = 0; k < uv.size(); ++k) {
        const double u = uv[k].x / spread, w = uv[k].y / spread;
        const double t[kTerms] = {1, u, w, u * u, u * w, w * w};
        for (int i = 0; i < kTerms; ++i) {
            for (int j = 0; j < kTerms; ++j) m[i][j] += t[i] * t[j];
            for (int ch = 0; ch < 3; ++ch) rhs[ch][i] += t[i] * values[k][ch];
        }
    }
    // Gaussian elimination with partial pivoting, the three channels at once.
    for (int c = 0; c < kTerms; ++c) {
        int pivot = c;
        for (int r = c + 1; r < kTerms; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
        if (std::abs(m[pivot][c]) < 1e-9 * m[0][0]) return false;
        for (int j = 0; j < kTerms; ++j) std::swap(m[c][j], m[pivot][j]);
        for (int ch = 0; ch < 3; ++ch) std::swap(rhs[ch][c], rhs[ch][pivot]);
        for (int r = c + 1; r < kTerms; ++r) {
            const double f = m[r][c] / m[c][c];
            for (int j = c; j < kTerms; ++j) m[r][j] -= f * m[c][j];
            for (int ch = 0; ch < 3; ++ch) rhs[ch][r] -= f * rhs[ch][c];
        }
    }
    for (int ch = 0; ch < 3; ++ch) {
        double x[kTerms];
        for (int r = kTerms - 1; r >= 0; --r) {
            double sum = rhs[ch][r];
            for (int j = r + 1; j < kTerms; ++j) sum -= m[r][j] * x[j];
            x[r] = sum / m[r][r];
        }
        out[ch] = x[0];
    }
    return true;
}

}  // namespace

void reconstructVertices(const PatchMesh& mesh, RadiositySolution& solution, bool linear) {
    const size_t nv = mesh.vertices.size();
    std::vector<std::vector<uint32_t>> around(nv);  // vertex → patches sharing it
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t v : mesh.patches[i].v) around[v].push_back(i);

    solution.vertexIndirect.assign(nv, Rgb(0.0));
    const std::vector<double> angleSum = vertexAngleSums(mesh);
    for (size_t v = 0; v < nv; ++v) {
        if (around[v].empty()) continue;
        // A covered patch (a lamp hung just below it) does not receive the open surface's
        // light: where v has open patches, only they count (before, the ceiling's vertices
        // around the Cornell box's lamp read 13-30 % below a gather).
        auto isOpen = [&](uint32_t i) { return mesh.covered.empty() || !mesh.covered[i]; };
        const bool anyOpen = std::any_of(around[v].begin(), around[v].end(), isOpen);
        auto counts = [&](uint32_t i) { return !anyOpen || isOpen(i); };
        Rgb sum(0.0);
        double count = 0;
        for (uint32_t i : around[v])
            if (counts(i)) sum += solution.indirect[i], count += 1;
        Rgb average = sum / count;  // the paper's reconstruction
        solution.vertexIndirect[v] = average;
        if (!linear) continue;

        // Two rings of patches around v, in v's surface group.
        std::set<uint32_t> ring;
        for (uint32_t i : around[v])
            for (uint32_t w : mesh.patches[i].v)
                for (uint32_t j : around[w])
                    if (counts(j)) ring.insert(j);
        Vec3 n(0.0);
        for (uint32_t i : around[v]) n += mesh.patches[i].normal * mesh.patches[i].area;
        if (glm::length(n) == 0) continue;
        n = glm::normalize(n);
        const auto [t1, t2] = tangentFrame(n);
        std::vector<Vec2> uv;
        std::vector<Rgb> values;
        for (uint32_t i : ring) {
            if (mesh.patches[i].group != mesh.patches[around[v][0]].group) continue;
            Vec3 d = mesh.patches[i].centroid - mesh.vertices[v];
            uv.emplace_back(glm::dot(d, t1), glm::dot(d, t2));
            values.push_back(solution.indirect[i]);
        }
        Rgb fitted;
        // Inside a surface, where the samples surround the vertex, a quadratic: a plane
        // through a curved field lies above it where the field is convex (the light on a
        // block's face falling toward its top). On a rim it would extrapolate: a plane.
        // Illuminance is never negative; a fit across a sharp shadow edge could be.
        if ((isInnerVertex(angleSum[v]) && quadraticAtOrigin(uv, values, fitted)) || planeAtOrigin(uv, values, fitted))
            solution.vertexIndirect[v] = glm::max(fitted, Rgb(0.0));
    }
}

}  // namespace rayrad::radiosity
