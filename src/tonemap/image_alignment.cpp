#include <tonemap/image_alignment.h>

#include <core/input_error.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace rayrad::tonemap {

namespace {

/// Solves the n × n system A x = b by Gaussian elimination with partial pivoting; false
/// when it is singular (relative to its scale).
bool solve(std::vector<std::vector<double>> A, std::vector<double> b, std::vector<double>& x) {
    const size_t n = b.size();
    double scale = 0;
    for (const auto& row : A)
        for (double v : row) scale = std::max(scale, std::abs(v));
    for (size_t c = 0; c < n; ++c) {
        size_t p = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::abs(A[r][c]) > std::abs(A[p][c])) p = r;
        if (!(std::abs(A[p][c]) > 1e-12 * scale)) return false;
        std::swap(A[p], A[c]);
        std::swap(b[p], b[c]);
        for (size_t r = c + 1; r < n; ++r) {
            const double f = A[r][c] / A[c][c];
            for (size_t k = c; k < n; ++k) A[r][k] -= f * A[c][k];
            b[r] -= f * b[c];
        }
    }
    x.assign(n, 0);
    for (size_t c = n; c-- > 0;) {
        double s = b[c];
        for (size_t k = c + 1; k < n; ++k) s -= A[c][k] * x[k];
        x[c] = s / A[c][c];
    }
    return true;
}

/// Translates points to their centroid and scales them to mean distance √2 (Hartley):
/// returns (scale, cx, cy) with x' = scale (x − cx).
std::array<double, 3> normaliser(const std::vector<std::array<double, 2>>& pts) {
    double cx = 0, cy = 0;
    for (const auto& p : pts) cx += p[0], cy += p[1];
    cx /= pts.size(), cy /= pts.size();
    double d = 0;
    for (const auto& p : pts) d += std::hypot(p[0] - cx, p[1] - cy);
    d /= pts.size();
    return {d > 0 ? std::sqrt(2.0) / d : 1.0, cx, cy};
}

}  // namespace

std::array<double, 2> mapPoint(const Homography& h, double x, double y) {
    const double w = h[6] * x + h[7] * y + h[8];
    return {(h[0] * x + h[1] * y + h[2]) / w, (h[3] * x + h[4] * y + h[5]) / w};
}

Homography fitHomography(const std::vector<PointPair>& pairs) {
    if (pairs.size() < 4)
        throw InputError(placeMessage("", "--align", fmt::format("a homography needs at least 4 point pairs, got {}", pairs.size())));
    std::vector<std::array<double, 2>> from, to;  // b → a
    for (const auto& p : pairs) from.push_back({p.bx, p.by}), to.push_back({p.ax, p.ay});
    const auto nf = normaliser(from), nt = normaliser(to);
    // Least squares on the normalised points: for each pair two rows of
    // [x y 1 0 0 0 −x X −y X | X] and [0 0 0 x y 1 −x Y −y Y | Y], h8 = 1.
    std::vector<std::vector<double>> AtA(8, std::vector<double>(8, 0.0));
    std::vector<double> Atb(8, 0.0);
    for (size_t i = 0; i < pairs.size(); ++i) {
        const double x = nf[0] * (from[i][0] - nf[1]), y = nf[0] * (from[i][1] - nf[2]);
        const double X = nt[0] * (to[i][0] - nt[1]), Y = nt[0] * (to[i][1] - nt[2]);
        const double rows[2][9] = {{x, y, 1, 0, 0, 0, -x * X, -y * X, X}, {0, 0, 0, x, y, 1, -x * Y, -y * Y, Y}};
        for (const auto& r : rows)
            for (int j = 0; j < 8; ++j) {
                for (int k = 0; k < 8; ++k) AtA[j][k] += r[j] * r[k];
                Atb[j] += r[j] * r[8];
            }
    }
    std::vector<double> h;
    if (!solve(AtA, Atb, h))
        throw InputError(placeMessage("", "--align", "the points do not determine a homography (three or more on one line?)"));
    // Undo the normalisations: H = T_to⁻¹ · Hn · T_from.
    const double Hn[3][3] = {{h[0], h[1], h[2]}, {h[3], h[4], h[5]}, {h[6], h[7], 1}};
    const double Tf[3][3] = {{nf[0], 0, -nf[0] * nf[1]}, {0, nf[0], -nf[0] * nf[2]}, {0, 0, 1}};
    const double Ti[3][3] = {{1 / nt[0], 0, nt[1]}, {0, 1 / nt[0], nt[2]}, {0, 0, 1}};
    double M[3][3] = {}, H[3][3] = {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) M[i][j] += Hn[i][k] * Tf[k][j];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) H[i][j] += Ti[i][k] * M[k][j];
    Homography out;
    for (int i = 0; i < 9; ++i) out[i] = H[i / 3][i % 3] / H[2][2];
    return out;
}

HdrImage warpOnto(const HdrImage& a, const Homography& bToA, int width, int height) {
    HdrImage out(width, height);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto p = mapPoint(bToA, x + 0.5, y + 0.5);
            // Bilinear between the four pixel centres around p.
            const double u = p[0] - 0.5, v = p[1] - 0.5;
            if (!(u >= 0 && v >= 0 && u <= a.width - 1 && v <= a.height - 1)) {
                out.at(x, y) = Rgb(nan);
                continue;
            }
            const int i = std::min(static_cast<int>(u), a.width - 2 < 0 ? 0 : a.width - 2);
            const int j = std::min(static_cast<int>(v), a.height - 2 < 0 ? 0 : a.height - 2);
            const double s = u - i, t = v - j;
            const int i1 = std::min(i + 1, a.width - 1), j1 = std::min(j + 1, a.height - 1);
            out.at(x, y) = (1 - s) * (1 - t) * a.at(i, j) + s * (1 - t) * a.at(i1, j) + (1 - s) * t * a.at(i, j1) +
                           s * t * a.at(i1, j1);
        }
    return out;
}

}  // namespace rayrad::tonemap
