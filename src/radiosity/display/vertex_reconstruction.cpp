#include <radiosity/display/vertex_reconstruction.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace rayrad::radiosity {

namespace {

/// Samples a quadratic fit needs around a vertex (6 terms, with some to spare); a plane's: 3.
constexpr size_t kQuadraticSamples = 10, kPlaneSamples = 3;

/// The least-squares fit through (u, w, value) samples of the first `terms` of
/// a + b u + c w + d u² + e uw + f w² (3: a plane, 6: a quadratic), its value a at (0, 0);
/// false when there are fewer than `minSamples` or their positions do not fix the terms
/// (a plane's samples on one line).
bool fitAtOrigin(const std::vector<Vec2>& uv, const std::vector<Rgb>& values, int terms, size_t minSamples, Rgb& out) {
    constexpr int kMaxTerms = 6;
    if (uv.size() < minSamples) return false;
    // Scaled to the samples' spread, so the normal equations are well conditioned.
    double spread = 0;
    for (const Vec2& p : uv) spread = std::max(spread, glm::length(p));
    if (!(spread > 0)) return false;
    double m[kMaxTerms][kMaxTerms] = {}, rhs[3][kMaxTerms] = {};
    for (size_t k = 0; k < uv.size(); ++k) {
        const double u = uv[k].x / spread, w = uv[k].y / spread;
        const double t[kMaxTerms] = {1, u, w, u * u, u * w, w * w};
        for (int i = 0; i < terms; ++i) {
            for (int j = 0; j < terms; ++j) m[i][j] += t[i] * t[j];
            for (int ch = 0; ch < 3; ++ch) rhs[ch][i] += t[i] * values[k][ch];
        }
    }
    // Gaussian elimination with partial pivoting, the three channels at once.
    for (int c = 0; c < terms; ++c) {
        int pivot = c;
        for (int r = c + 1; r < terms; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
        if (std::abs(m[pivot][c]) < 1e-9 * m[0][0]) return false;
        for (int j = 0; j < terms; ++j) std::swap(m[c][j], m[pivot][j]);
        for (int ch = 0; ch < 3; ++ch) std::swap(rhs[ch][c], rhs[ch][pivot]);
        for (int r = c + 1; r < terms; ++r) {
            const double f = m[r][c] / m[c][c];
            for (int j = c; j < terms; ++j) m[r][j] -= f * m[c][j];
            for (int ch = 0; ch < 3; ++ch) rhs[ch][r] -= f * rhs[ch][c];
        }
    }
    for (int ch = 0; ch < 3; ++ch) {
        double x[kMaxTerms];
        for (int r = terms - 1; r >= 0; --r) {
            double sum = rhs[ch][r];
            for (int j = r + 1; j < terms; ++j) sum -= m[r][j] * x[j];
            x[r] = sum / m[r][r];
        }
        out[ch] = x[0];
    }
    return true;
}

}  // namespace

void reconstructVertices(const PatchMesh& mesh, RadiositySolution& solution, bool linear) {
    const size_t nv = mesh.vertices.size();
    const std::vector<std::vector<uint32_t>> around = patchesAround(mesh);

    solution.vertexIndirect.assign(nv, Rgb(0.0));
    const std::vector<double> angleSum = vertexAngleSums(mesh);
    for (size_t v = 0; v < nv; ++v) {
        if (around[v].empty()) continue;
        // A covered patch (a lamp hung just below it) does not receive the open surface's
        // light: where v has open patches, only they count (before, the ceiling's vertices
        // around the Cornell box's lamp read 13-30 % below a gather).
        auto isOpen = [&](uint32_t i) { return !mesh.isCovered(i); };
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
        if ((isInnerVertex(angleSum[v]) && fitAtOrigin(uv, values, 6, kQuadraticSamples, fitted)) ||
            fitAtOrigin(uv, values, 3, kPlaneSamples, fitted))
            solution.vertexIndirect[v] = glm::max(fitted, Rgb(0.0));
    }
}

}  // namespace rayrad::radiosity
