// Daylight through openings: an opening's light at a receiver, part by part; what comes in
// through the openings; the glazing the sun and the ray tracer's rays cross.
#include <radiosity/direct/direct_light.h>

#include <core/ray_batch.h>
#include <radiosity/form_factors/form_factor.h>
#include <scene/daylight/glazing.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace rayrad::radiosity {

namespace {
/// An opening is cut into at least this many parts: the sky's luminance changes across it.
constexpr int kOpeningSamples = 16;
/// Near the receiver its parts are split until each spans at most this fraction of its
/// distance (about 30°), at most this many times.
constexpr double kOpeningPartSpan = 0.5;
constexpr int kOpeningMaxDepth = 6;
/// A piece that spans more than this fraction of its distance gets its exact form factor;
/// smaller ones their point form factor, scaled so that all of them add up to the exact F.
constexpr double kExactPieceSpan = 0.5;

/// Visibility with nothing in the way (an opening's luminance factor, without rays).
struct NoOcclusion : Visibility {
    bool visible(const Vec3&, const Vec3&) const override { return true; }
};

/// One opening's light at a receiver x (unit normal n), part by part: each part split into
/// pieces near x; piece c sees the sky along the direction to its centroid ω_c and delivers
/// π F_c L(ω_c) τ(θ_c). The pieces resolve the sky's luminance; the shadows are sampled
/// like a lamp's: one shadow ray per part, through a point of one of its pieces chosen in
/// proportion to its light, whose visibility the whole part takes.
class OpeningIntegral {
  public:
    OpeningIntegral(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility* vis, Random* rng,
                    double beyondScene)
        : m_light(light), m_x(x), m_n(n), m_vis(vis), m_rng(rng), m_beyondScene(beyondScene),
          m_up(glm::transpose(light.skyFrame) * light.sky->up),  // as seen through a mirror image
          m_shadowRays(vis ? *vis : m_none, x, n, m_shadowed) {}

    /// One part of the opening (a triangle of its grid): its pieces, then its shadow ray.
    void addPart(const std::array<Vec3, 3>& t) {
        m_pieces.clear();
        m_partLight = Vec2(0.0);
        split(t, 0);
        if (m_vis) shadowRay();
    }

    /// The light, lx, given the opening's exact form factor F (the far pieces share what the
    /// near ones leave of it); `open` (if given) gets it without shadows.
    double finish(double exactF, double* open) {
        m_shadowRays.flush();
        double result = m_shadowed.x;
        if (m_farWeights > 0) {
            // The far pieces' share of the exact F, π (F − Σ near F_c) Σ w L (V) / Σ w.
            const double rest = std::max(0.0, exactF - m_nearF);
            m_unshadowed += kPi * rest * m_farOpen / m_farWeights;
            result += kPi * rest * m_shadowed.y / m_farWeights;
        }
        if (open) *open = m_unshadowed;
        return m_vis ? result : m_unshadowed;
    }

  private:
    /// A piece: its outline, and its light (near: π F L, lx; far: w L).
    struct Piece {
        std::array<Vec3, 4> corner;
        int count;
        double light;
    };

    /// A part: split in four while it spans more than kOpeningPartSpan of its distance from
    /// x (near x the luminance and the glazing's τ change across a part faster than its
    /// centroid's direction can say); a part the horizon crosses is cut there, so the sky
    /// above and the ground below each get their own piece.
    void split(const std::array<Vec3, 3>& t, int depth) {
        const Vec3 centroid = (t[0] + t[1] + t[2]) / 3.0;
        const double span = std::max({glm::length(t[1] - t[0]), glm::length(t[2] - t[1]), glm::length(t[0] - t[2])});
        if (depth < kOpeningMaxDepth && span > kOpeningPartSpan * glm::length(centroid - m_x)) {
            const Vec3 m01 = 0.5 * (t[0] + t[1]), m12 = 0.5 * (t[1] + t[2]), m20 = 0.5 * (t[2] + t[0]);
            for (const auto& child : {std::array<Vec3, 3>{t[0], m01, m20}, std::array<Vec3, 3>{m01, t[1], m12},
                                      std::array<Vec3, 3>{m20, m12, t[2]}, std::array<Vec3, 3>{m01, m12, m20}})
                split(child, depth + 1);
            return;
        }
        double h[3];
        for (int k = 0; k < 3; ++k) h[k] = glm::dot(m_up, t[k] - m_x);  // m above x's horizon
        if (std::min({h[0], h[1], h[2]}) >= 0 || std::max({h[0], h[1], h[2]}) <= 0) {
            deliver(t.data(), 3);
            return;
        }
        // Cut at the horizon: the corners on each side, and the two crossings.
        Vec3 above[4], below[4];
        int na = 0, nb = 0;
        for (int k = 0; k < 3; ++k) {
            const Vec3 &a = t[k], &b = t[(k + 1) % 3];
            const double ha = h[k], hb = h[(k + 1) % 3];
            if (ha >= 0) above[na++] = a;
            if (ha < 0) below[nb++] = a;
            if ((ha < 0) != (hb < 0)) {
                const Vec3 cut = a + (ha / (ha - hb)) * (b - a);
                above[na++] = cut, below[nb++] = cut;
            }
        }
        deliver(above, na);
        deliver(below, nb);
    }

    /// A piece of the opening (a triangle, or a part of one the horizon cut off) delivers
    /// π F L(ω) τ along the direction ω to its centroid. Near pieces (spanning more than
    /// kExactPieceSpan of their distance) with their exact form factors F_c: lx. Far ones
    /// share what the near ones leave of the opening's exact F, in proportion to their point
    /// form factors w_c = A cosθ_x cosθ_y / (π r²): Σ w_c L_c V_c, Σ w_c L_c and Σ w_c.
    void deliver(const Vec3* piece, int count) {
        Vec3 centroid(0.0);
        for (int k = 0; k < count; ++k) centroid += piece[k];
        centroid /= static_cast<double>(count);
        const Vec3 d = centroid - m_x;
        const double r2 = glm::dot(d, d);
        double span = 0;
        for (int k = 0; k < count; ++k) span = std::max(span, glm::length(piece[k] - piece[(k + 1) % count]));
        const bool far = span * span < kExactPieceSpan * kExactPieceSpan * r2;
        double f = 0;
        if (far) {
            Vec3 area(0.0);  // the piece's vector area
            for (int k = 1; k + 1 < count; ++k) area += 0.5 * glm::cross(piece[k] - piece[0], piece[k + 1] - piece[0]);
            f = std::max(0.0, glm::dot(m_n, d)) * std::max(0.0, -glm::dot(area, d)) / (kPi * r2 * r2);
        } else {
            f = formFactorToPolygon(m_x, m_n, piece, count, m_light.normal);
        }
        if (f <= 0) return;
        const auto along = unitDirection(d);
        if (!along) return;
        const double l = m_light.skyLuminanceAlong(*along);  // cd/m²
        if (far) {
            m_farWeights += f;
            m_farOpen += f * l;
            m_partLight.y += f * l;
        } else {
            m_nearF += f;
            m_unshadowed += kPi * f * l;
            m_partLight.x += kPi * f * l;
        }
        if (!m_vis) return;
        Piece p{{}, count, kPi * f * l};  // lx, about its share of the result (far: before rescaling)
        for (int k = 0; k < count; ++k) p.corner[k] = piece[k];
        m_pieces.push_back(p);
    }

    /// The part's shadow ray: through a point of one of its pieces (chosen in proportion to
    /// its light; a uniform point of it when jittered, else its centroid), on beyond the
    /// scene; the part's light counts where it is clear.
    void shadowRay() {
        double total = 0;
        for (const Piece& p : m_pieces) total += p.light;
        if (total <= 0) return;
        double u = (m_rng ? m_rng->nextDouble() : 0.5) * total;
        size_t c = 0;
        while (c + 1 < m_pieces.size() && u >= m_pieces[c].light) u -= m_pieces[c++].light;
        const Piece& p = m_pieces[c];
        Vec3 y(0.0);
        for (int k = 0; k < p.count; ++k) y += p.corner[k];
        y /= static_cast<double>(p.count);
        if (m_rng) {  // in one of its fan triangles, chosen by area
            int k = 1;
            if (p.count == 4) {
                const double a1 = glm::length(glm::cross(p.corner[1] - p.corner[0], p.corner[2] - p.corner[0]));
                const double a2 = glm::length(glm::cross(p.corner[2] - p.corner[0], p.corner[3] - p.corner[0]));
                if (m_rng->nextDouble() * (a1 + a2) > a1) k = 2;
            }
            double a = m_rng->nextDouble(), b = m_rng->nextDouble();
            if (a + b > 1) a = 1 - a, b = 1 - b;
            y = p.corner[0] + a * (p.corner[k] - p.corner[0]) + b * (p.corner[k + 1] - p.corner[0]);
        }
        if (const auto through = unitDirection(y - m_x)) m_shadowRays.add(y + m_beyondScene * *through, m_partLight);
    }

    const AreaLight& m_light;
    const Vec3 m_x, m_n;
    const Visibility* m_vis;
    Random* m_rng;
    const double m_beyondScene;
    const Vec3 m_up;  ///< the sky's up in the opening's frame
    // Near lx and far Σ w L, and their sums: unshadowed, and over the visible parts.
    double m_unshadowed = 0, m_nearF = 0, m_farWeights = 0, m_farOpen = 0;
    Vec2 m_shadowed{0.0};   ///< the visible parts' (near lx, far Σ w L)
    Vec2 m_partLight{0.0};  ///< the current part's (near, far) light
    const NoOcclusion m_none;
    RayBatch<Vec2> m_shadowRays;
    /// The current part's pieces (kept per thread: no allocation per receiver).
    static thread_local std::vector<Piece> m_pieces;
};

thread_local std::vector<OpeningIntegral::Piece> OpeningIntegral::m_pieces;

}  // namespace

double AreaLight::skyLuminanceAlong(const Vec3& w) const {
    const double cosTheta = -glm::dot(w, normal);  // the opening's normal faces the receiver
    return skyWeight * sky->luminance(skyFrame * w) * scene::glazingTransmittance(transmittance, cosTheta);
}

double enteringIlluminance(const scene::Daylight& daylight, const Vec3& inward, double transmittance) {
    // Midpoint rule over the hemisphere of directions w leaving the room (w · inward < 0),
    // in (cosθ, φ) about −inward: dω = d(cosθ) dφ.
    const Vec3 out = -inward;
    const auto [t, b] = tangentFrame(out);
    constexpr int kRings = 256, kSectors = 512;
    double sum = 0;
    for (int i = 0; i < kRings; ++i) {
        const double c = (i + 0.5) / kRings, s = std::sqrt(1 - c * c);
        const double tau = scene::glazingTransmittance(transmittance, c);
        double ring = 0;
        for (int j = 0; j < kSectors; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / kSectors;
            ring += daylight.luminance(c * out + s * (std::cos(phi) * t + std::sin(phi) * b));
        }
        sum += ring * tau * c;
    }
    return sum * (1.0 / kRings) * (2 * kPi / kSectors);
}

void DirectLight::measureEntering(const Visibility& vis) {
    if (m_openings.empty()) return;
    // Per triangle of an opening, from 8 × 8 points on it: the share of the sky's light
    // (L τ, 16 × 32 cosine-distributed directions outward) whose ray is clear, times the
    // unobstructed sky's exact Φ; and the share of the points the sun reaches, times its Φ.
    constexpr int kPoints = 8, kRings = 16, kSectors = 32;
    double flux = 0, through = 0;
    for (size_t i : m_openings) {
        const AreaLight& o = m_areaLights[i];
        const Vec3 out = -o.normal;
        const auto [t1, t2] = tangentFrame(out);
        const double cosSun = glm::dot(m_daylight->sunDirection, out);
        const double sunIlluminance =
            m_sun >= 0 && cosSun > 0
                ? m_daylight->sunNormalIlluminance * scene::glazingTransmittance(o.transmittance, cosSun) * cosSun
                : 0.0;  // lx on the opening, unobstructed
        const double skyIlluminance = kPi * o.luminance.g;  // lx, the unobstructed sky and ground through it
        for (size_t t = 0; t < o.triangles.size(); ++t) {
            const auto& tri = o.triangles[t];
            double seen = 0, all = 0, straight = 0;
            int sunlit = 0, sunThrough = 0;
            for (int a = 0; a < kPoints; ++a)
                for (int b = 0; b < kPoints; ++b) {
                    double u = (a + 0.5) / kPoints, v = (b + 0.5) / kPoints;
                    if (u + v > 1) u = 1 - u, v = 1 - v;
                    const Vec3 y = tri[0] + u * (tri[1] - tri[0]) + v * (tri[2] - tri[0]);
                    for (int r = 0; r < kRings; ++r)
                        for (int k = 0; k < kSectors; ++k) {
                            const double q = (r + 0.5) / kRings, phi = 2 * kPi * (k + 0.5) / kSectors;
                            const double c = std::sqrt(1 - q), sn = std::sqrt(q);
                            const Vec3 w = c * out + sn * (std::cos(phi) * t1 + std::sin(phi) * t2);
                            const double l = m_daylight->luminance(w) * scene::glazingTransmittance(o.transmittance, c);
                            all += l;
                            if (!vis.visible(y, y + m_beyondScene * w)) continue;
                            seen += l;
                            // Light that comes in along −w and meets nothing leaves again
                            // through another opening (or the same bay's) untouched.
                            if (vis.visible(y, y - m_beyondScene * w)) straight += l;
                        }
                    const Vec3& toSun = m_daylight->sunDirection;
                    if (sunIlluminance > 0 && vis.visible(y, y + m_beyondScene * toSun)) {
                        ++sunlit;
                        if (vis.visible(y, y - m_beyondScene * toSun)) ++sunThrough;
                    }
                }
            const double share = all > 0 ? seen / all : 0.0, straightShare = all > 0 ? straight / all : 0.0;
            const double points = kPoints * kPoints;
            flux += o.triangleAreas[t] * (skyIlluminance * share + sunIlluminance * sunlit / points);
            through += o.triangleAreas[t] * (skyIlluminance * straightShare + sunIlluminance * sunThrough / points);
        }
    }
    m_enteringMeasured = flux;
    m_passingThrough = through;
}

double DirectLight::glazingFor(const scene::PointLight& l, const Vec3& x) const {
    if (m_sun < 0 || &l != &m_pointLights[m_sun]) return 1.0;
    return openingTransmittance(x, m_daylight->sunDirection, m_beyondScene);
}

int DirectLight::openingsCrossed(const Vec3& x, const Vec3& w, double maxDistance, double* tau) const {
    int crossed = 0;
    for (size_t i : m_openings) {
        const AreaLight& o = m_areaLights[i];
        const double c = glm::dot(w, o.normal);
        if (c == 0) continue;
        const double t = glm::dot(o.centre - x, o.normal) / c;  // the ray meets the opening's plane
        if (!(t > 0 && t < maxDistance)) continue;
        const Vec3 p = x + t * w;
        for (const auto& tri : o.triangles)
            if (const Vec3 b = barycentric(tri[0], tri[1], tri[2], p); b.x >= 0 && b.y >= 0 && b.z >= 0) {
                if (tau) *tau *= scene::glazingTransmittance(o.transmittance, std::abs(c));
                ++crossed;
                break;
            }
    }
    return crossed;
}

double DirectLight::openingFormFactor(size_t k, const Vec3& x, const Vec3& n, const Visibility& vis,
                                      int samples) const {
    AreaLight outline = m_areaLights[m_openings[k]];
    outline.sky = nullptr;  // its outline only
    const double f = areaLightFormFactor(outline, x, n);
    return f > 0 ? f * visibleFraction(outline, x, n, &vis, samples, nullptr) : 0.0;
}

double DirectLight::throughOpening(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility* vis,
                                   int samples, Random* rng, double* open) const {
    // Each triangle of the outline cut into m² equal parts (a barycentric grid).
    samples = std::max(samples, kOpeningSamples);
    const int m = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(samples) /
                                                                    static_cast<double>(light.triangles.size())))));
    OpeningIntegral integral(light, x, n, vis, rng, m_beyondScene);
    for (const auto& t : light.triangles) {
        const Vec3 e1 = (t[1] - t[0]) / static_cast<double>(m), e2 = (t[2] - t[0]) / static_cast<double>(m);
        for (int i = 0; i < m; ++i)
            for (int j = 0; i + j < m; ++j) {
                const Vec3 a = t[0] + static_cast<double>(i) * e1 + static_cast<double>(j) * e2;
                integral.addPart({a, a + e1, a + e2});
                if (i + j + 1 < m) integral.addPart({a + e1, a + e1 + e2, a + e2});  // the grid's downward triangles
            }
    }
    return integral.finish(areaLightFormFactor(light, x, n), open);
}

}  // namespace rayrad::radiosity
