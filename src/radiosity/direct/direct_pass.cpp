#include <radiosity/direct/direct_pass.h>

#include <core/hash.h>
#include <core/random.h>

#include <radiosity/direct/sealed_solids.h>
#include <radiosity/direct/shared_corners.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/mesh/contact_outlines.h>
#include <radiosity/mesh/mesh_location.h>
#include <radiosity/mesh/mesher.h>
#include <radiosity/solution/light_value.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <unordered_map>

namespace rayrad::radiosity {

namespace {

/// The 4-point rule over a triangle: (3/4) f(c) + (1/12) Σ f(v_k), exact for quadratics.
template <class T>
T fourPointMean(const T& centre, const T* corners) {
    return 0.75 * centre + (corners[0] + corners[1] + corners[2]) / 12.0;
}

/// Points at which a partly shadowed patch is sampled, as barycentric (u, v) of corners
/// 1 and 2: Roberts' R2 low-discrepancy sequence on the unit square, folded into the
/// triangle (u + v > 1 → 1 − u, 1 − v), equal weights. A regular lattice lines up with
/// the straight shadow edges of boxes on a grid-meshed floor and is biased there (+0.17 %
/// of the direct flux in a room with a block); R2 is not (0.02 %).
std::vector<std::array<double, 2>> shadowSamplePoints(int count) {
    const double g = 1.32471795724474602596;  // the plastic number, g³ = g + 1
    std::vector<std::array<double, 2>> out;
    for (int k = 1; k <= count; ++k) {
        double u = std::fmod(0.5 + k / g, 1.0), v = std::fmod(0.5 + k / (g * g), 1.0);
        if (u + v > 1) u = 1 - u, v = 1 - v;
        out.push_back({u, v});
    }
    return out;
}

/// Patches a thread takes at a time: their shared corners are evaluated once in it
/// (CornerValues). A few rows of a large surface's grid.
constexpr size_t kChunkPatches = 1024;

/// Shadow rays per point source on a partly shadowed patch.
constexpr int kShadowSamples = 64;
/// Sample points for an area light whose shadow edge crosses a patch: kShadowSamples for
/// the patch's strongest light, fewer (the first of the same sequence) in proportion to
/// a weaker light's unshadowed illuminance, so each light's error in lx is about the
/// strongest one's; at least this many. (In the bench hall, 100 troffers, a floor patch
/// is crossed by the shadow edges of a dozen weak lights: a floor of 16 gave them 2.5
/// times the points the rule asks for and cost 2.2 of the direct pass's 12 CPU-s. Against
/// 256 points for every light, the image is within 0.03 % at the 95th percentile with 4,
/// 0.016 % with 16, and grids of 200 sensors on floor and ceiling within 0.17 % with
/// either.)
constexpr int kMinAreaShadowSamples = 4;

/// The direct light at one evaluation point: where it is, the total E (lx) and each
/// source's share and unshadowed value (DirectLight::illuminance's perSource/perSourceOpen).
struct PointValues {
    Vec3 x{0.0};
    Rgb e{0.0};
    std::vector<Rgb> share, open;
};

/// The shadow rays' jitter at x: seeded by the point, so the pass is deterministic, and
/// the strata's jitter differs from point to point. (Cell centres at every point would
/// bias a partly hidden light's visible fraction the same way everywhere: through a
/// window's reveals, +3.5 % at 16 rays.)
Random pointRandom(const Vec3& x) {
    Hash h;
    h << x;
    return Random(h.value());
}

void evaluateAt(PointValues& out, const Vec3& x, const Vec3& normal, const DirectLight& lights, const Visibility& vis,
                int areaSamples) {
    out.x = x;
    Random rng = pointRandom(x);
    out.e = lights.illuminance(x, normal, vis, areaSamples, &rng, &out.share, &out.open);
}

/// The corner values a run of patches shares (sharedCorners): each (vertex, side) is
/// evaluated once at the vertex itself. A thread keeps one for a chunk of consecutive
/// patches (the premesher makes a surface's patches row by row, so most of a chunk's
/// corners are shared within it); a corner on a chunk's border is evaluated by both, alike.
class CornerValues {
  public:
    /// Starts a chunk; `shared` (sharedCorners) says which vertices are shared.
    void start(const std::vector<char>& shared) {
        m_shared = &shared;
        m_slot.clear();
        m_used = 0;
    }
    bool shares(uint32_t v) const { return (*m_shared)[v] != 0; }
    /// Vertex v's values for the side facing `normal` (back: the reverse side).
    const PointValues& at(const PatchMesh& mesh, uint32_t v, bool back, const Vec3& normal, const DirectLight& lights,
                          const Visibility& vis, int areaSamples) {
        const uint64_t key = 2 * uint64_t(v) + (back ? 1 : 0);
        auto [it, added] = m_slot.emplace(key, m_used);
        if (!added) return m_values[it->second];
        if (m_used == m_values.size()) m_values.emplace_back();
        PointValues& out = m_values[m_used++];
        evaluateAt(out, mesh.vertices[v], normal, lights, vis, areaSamples);
        return out;
    }

  private:
    const std::vector<char>* m_shared = nullptr;
    std::unordered_map<uint64_t, size_t> m_slot;
    std::deque<PointValues> m_values;  ///< stable references; kept between chunks (their vectors' capacity)
    size_t m_used = 0;
};

/// Deepest split, and tolerance, of the solid-angle integral of a point source whose
/// intensity varies with direction (a spot, a luminaire).
constexpr int kIntensityMaxDepth = 6;
/// Within this many opening sizes of a luminaire, the direct pass integrates over its
/// opening's parts (see pointSourceMean).
constexpr double kOpeningKernelSizes = 5.0;
constexpr double kIntensityRelTolerance = 1e-4;

/// ∫ Y(I(ω)) dω over the solid angle triangle t subtends from point source s (at
/// `source`), lm: Ω × Y(I toward the centroid), the triangle split in four until the
/// sum over the children agrees with it.
double intensityOverSolidAngle(const DirectLight& lights, size_t s, const Vec3& source, const std::array<Vec3, 3>& t,
                               int depth) {
    auto coarse = [&](const std::array<Vec3, 3>& u) {
        const Vec3 d = (u[0] + u[1] + u[2]) / 3.0 - source;
        const double r = glm::length(d);
        return r > 0 ? triangleSolidAngle(source, u[0], u[1], u[2]) *
                           luminance(lights.pointSourceIntensityAlong(s, d / r))
                     : 0.0;
    };
    const Vec3 m01 = 0.5 * (t[0] + t[1]), m12 = 0.5 * (t[1] + t[2]), m20 = 0.5 * (t[2] + t[0]);
    const std::array<Vec3, 3> child[4] = {{t[0], m01, m20}, {m01, t[1], m12}, {m20, m12, t[2]}, {m01, m12, m20}};
    double fine = 0;
    for (const auto& c : child) fine += coarse(c);
    const double whole = coarse(t);
    if (depth >= kIntensityMaxDepth || std::abs(fine - whole) <= kIntensityRelTolerance * std::abs(fine)) return fine;
    double sum = 0;
    for (const auto& c : child) sum += intensityOverSolidAngle(lights, s, source, c, depth + 1);
    return sum;
}

/// Mean illuminance (lx) over patch p from point source s, given its values at the
/// evaluation points. A point source's E = I cosθ V / d² peaks sharply on a patch it is
/// close to, and the 4-point rule misses that. Without shadows the mean of
/// I cosθ / d² over the patch is (1/A) ∫ I dω over the solid angle Ω it subtends: I Ω / A
/// for a point light, integrated over Ω for a spot or a luminaire. The rule's value is
/// rescaled by that over the rule's own unshadowed value, so a source that sees the
/// whole patch delivers exactly ∫ I dω. When the four points
/// disagree (a shadow edge or a spot's rim crosses the patch) the rule is replaced by the
/// mean over the `refined` points; so it is when `refine` is set (a mirror's rim may
/// cross the patch).
Rgb pointSourceMean(const PatchMesh& mesh, const Patch& p, const Vec3& normal, const DirectLight& lights, size_t s,
                    const Visibility& vis, const std::array<Vec3, 4>& points, const Rgb* values, const Rgb& fourPoint,
                    const std::vector<std::array<double, 2>>& refined, bool refine) {
    // The rescaling below corrects the rule's sampling of a peaked kernel. Close to a
    // luminaire (within kOpeningKernelSizes of its opening's size) the kernel is its
    // opening's parts' (each with an equal share of the distribution); farther, even in
    // its near field where the values come from the parts, the point kernel is close
    // enough and far cheaper.
    const std::vector<Vec3> sources = lights.emissionPoints(s, p.centroid, kOpeningKernelSizes);
    const bool isotropic = lights.isIsotropic(s);
    auto kernel = [&](const Vec3& x) {  // Y of the unshadowed E (lx), up to I for a point light
        double sum = 0;
        for (const Vec3& source : sources) {
            const double h = glm::dot(normal, source - x);  // m
            if (h <= 0) continue;
            const Vec3 d = x - source;
            const double r = glm::length(d);
            const double k = h / (r * r * r);  // cosθ / d², 1/m²
            sum += isotropic ? k : k * luminance(lights.pointSourceIntensityAlong(s, d / r));
        }
        return sum / static_cast<double>(sources.size());
    };
    bool above = false;  // some source in front of the patch's plane
    for (const Vec3& source : sources) above |= glm::dot(normal, source - p.centroid) > 0;
    if (!above) return fourPoint;
    Rgb value = fourPoint;
    double ruleKernel = 0;
    int lit = 0;
    for (int k = 0; k < 4; ++k) lit += values[k] != Rgb(0.0);
    if (lit == 4 && !refine) {
        double kernels[4];
        for (int k = 0; k < 4; ++k) kernels[k] = kernel(points[k]);
        ruleKernel = fourPointMean(kernels[3], kernels);
    } else {
        const Vec3 a = mesh.corner(p, 0), ab = mesh.corner(p, 1) - a, ac = mesh.corner(p, 2) - a;
        value = Rgb(0.0);
        for (const auto& uv : refined) {
            Vec3 x = a + uv[0] * ab + uv[1] * ac;
            value += lights.fromPointSource(s, x, normal, vis);
            ruleKernel += kernel(x);
        }
        value /= static_cast<double>(refined.size());
        ruleKernel /= static_cast<double>(refined.size());
    }
    const std::array<Vec3, 3> t{mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
    double exactKernel = 0;  // the mean over the sources of (1/A) ∫ I dω over the patch
    for (const Vec3& source : sources)
        exactKernel += (isotropic ? triangleSolidAngle(source, t[0], t[1], t[2])
                                  : intensityOverSolidAngle(lights, s, source, t, 0)) /
                       p.area;
    exactKernel /= static_cast<double>(sources.size());
    return ruleKernel > 0 ? value * (exactKernel / ruleKernel) : fourPoint;
}

/// An area light is "near" a patch within this many patch diameters of its outline.
constexpr double kAreaNearDiameters = 4.0;
/// Adaptive integration of the unshadowed form factor: deepest split, and the tolerance
/// relative to the patch's own value (plus an absolute floor, in units of F).
constexpr int kAreaMaxDepth = 7;
constexpr double kAreaRelTolerance = 1e-4, kAreaAbsTolerance = 1e-7;

/// An opening's light over a patch: its form factor is integrated with its mean luminance,
/// and on each part of the patch this many splits down (or larger, where the integration
/// stops sooner) multiplied by the sky's luminance through it over that mean, at the part's
/// centroid (throughOpening: a few dozen form factors, too many for every point).
constexpr int kSkyFactorDepth = 2;

/// An opening's unshadowed light at x over π L̄ F (1 for a lamp, or where F is 0).
double skyFactorAt(const DirectLight& lights, size_t s, const Vec3& x, const Vec3& n) {
    const double geometric = luminance(lights.unshadowedFromAreaSource(s, x, n, false));
    return geometric > 0 ? luminance(lights.unshadowedFromAreaSource(s, x, n)) / geometric : 1.0;
}

/// ∫ π L F(x → light) dA_x over the triangle t (lx m²), by adaptive subdivision: a triangle is
/// split in four until the 4-point rule on it agrees with the sum over its children.
/// `rule` is the 4-point mean of π L F on t; `tolerance` in its units per m² of t. An
/// opening (`sky`): π L̄ F, times skyFactorAt on the parts kSkyFactorDepth down.
double integrateUnshadowed(const DirectLight& lights, size_t s, const std::array<Vec3, 3>& t, const Vec3& n,
                           double rule, double tolerance, int depth, bool sky) {
    const Vec3 centroid = (t[0] + t[1] + t[2]) / 3.0;
    if (sky && depth == kSkyFactorDepth)
        return integrateUnshadowed(lights, s, t, n, rule, tolerance, depth, false) *
               skyFactorAt(lights, s, centroid, n);
    const double area = 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
    auto F = [&](const Vec3& x) { return luminance(lights.unshadowedFromAreaSource(s, x, n, false)); };
    const Vec3 m01 = 0.5 * (t[0] + t[1]), m12 = 0.5 * (t[1] + t[2]), m20 = 0.5 * (t[2] + t[0]);
    const std::array<Vec3, 3> child[4] = {{t[0], m01, m20}, {m01, t[1], m12}, {m20, m12, t[2]}, {m01, m12, m20}};
    const double mid[3] = {F(m01), F(m12), F(m20)};
    const double corner[3] = {F(t[0]), F(t[1]), F(t[2])};
    const double at[4][3] = {{corner[0], mid[0], mid[2]},
                             {mid[0], corner[1], mid[1]},
                             {mid[2], mid[1], corner[2]},
                             {mid[0], mid[1], mid[2]}};
    double childRule[4], fine = 0;
    for (int k = 0; k < 4; ++k) {
        childRule[k] = fourPointMean(F((child[k][0] + child[k][1] + child[k][2]) / 3.0), at[k]);
        fine += childRule[k] * area / 4;
    }
    if (depth >= kAreaMaxDepth || std::abs(fine - rule * area) <= tolerance * area)
        return sky && depth < kSkyFactorDepth ? fine * skyFactorAt(lights, s, centroid, n) : fine;
    double sum = 0;
    for (int k = 0; k < 4; ++k)
        sum += integrateUnshadowed(lights, s, child[k], n, childRule[k], tolerance, depth + 1, sky);
    return sum;
}

/// Above this spread of the sky's factor between a patch's four points ((max − min) / max),
/// the sky's pattern through the opening changes across the patch — a bright part of the
/// sky seen through a window lights a sharp-edged footprint, as a sky patch of the daylight
/// coefficients does — and is not kept constant over it.
constexpr double kSkyFactorSpread = 0.2;

/// The sky's factor over a patch for an opening: the 4-point means of its unshadowed light
/// (`open`) over π L̄ F at the same points (`geometric`); nothing when the factors of the
/// four points spread more than kSkyFactorSpread.
std::optional<double> skyFactorOver(const double* open, const double* geometric) {
    double lo = std::numeric_limits<double>::max(), hi = 0;
    for (int k = 0; k < 4; ++k) {
        if (!(geometric[k] > 0)) continue;
        const double f = open[k] / geometric[k];
        lo = std::min(lo, f), hi = std::max(hi, f);
    }
    if (hi > 0 && hi - lo > kSkyFactorSpread * hi) return std::nullopt;
    const double mean = fourPointMean(geometric[3], geometric);
    return mean > 0 ? fourPointMean(open[3], open) / mean : 1.0;
}

/// The sky's factor over patch p for opening s (1 for a lamp): skyFactorOver its four points.
std::optional<double> patchSkyFactor(const DirectLight& lights, size_t s, const Vec3& normal,
                                     const std::array<Vec3, 4>& points, const Rgb* opens) {
    if (!lights.areaSource(s).sky) return 1.0;
    double geometric[4], open[4];
    for (int k = 0; k < 4; ++k) {
        geometric[k] = luminance(lights.unshadowedFromAreaSource(s, points[k], normal, false));
        open[k] = luminance(opens[k]);
    }
    return skyFactorOver(open, geometric);
}

/// Mean illuminance (lx) over patch p from area source s, or nullopt when the light is
/// far enough for the 4-point rule. Near an emitter (a ceiling 1 cm above a lamp that
/// faces it, a wall beside it) E = π L F changes from πL to 0 within a centimetre and the
/// rule misses it: the unshadowed mean is integrated adaptively, so a light that sees
/// whole patches delivers exactly its flux, and scaled by the visible fraction (shadows,
/// mirror apertures), taken from the four points or, where they disagree, from the
/// `refined` points.
/// `values` and `opens`: the source's shadowed and unshadowed E at the four points.
std::optional<Rgb> nearAreaSourceMean(const PatchMesh& mesh, const Patch& p, const Vec3& normal,
                                      const DirectLight& lights, size_t s, const Visibility& vis, int areaSamples,
                                      const Rgb* values, const Rgb* opens, const std::array<Vec3, 4>& points,
                                      const std::vector<std::array<double, 2>>& refined) {
    const AreaLight& light = lights.areaSource(s);
    if (glm::length(p.centroid - light.centre) - light.radius > kAreaNearDiameters * p.diameter) return std::nullopt;

    double unshadowed[4];
    for (int k = 0; k < 4; ++k) unshadowed[k] = luminance(opens[k]);
    const double rule = fourPointMean(unshadowed[3], unshadowed);
    // The rule the integration starts from: of π L F, for an opening with its mean luminance.
    double geometric[4];
    for (int k = 0; k < 4; ++k)
        geometric[k] =
            light.sky ? luminance(lights.unshadowedFromAreaSource(s, points[k], normal, false)) : unshadowed[k];
    const double geometricRule = fourPointMean(geometric[3], geometric);
    const std::array<Vec3, 3> t{mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
    const double exact = integrateUnshadowed(lights, s, t, normal, geometricRule,
                                             kAreaRelTolerance * geometricRule + kAreaAbsTolerance, 0,
                                             light.sky != nullptr) /
                         p.area;  // mean of Y(π L F) over the patch, lx
    if (exact <= 0) return Rgb(0.0);

    // Visible fraction: of the four points when each sees all or nothing alike, else sampled.
    bool agree = true;
    for (int k = 0; k < 4; ++k) agree &= std::abs(luminance(values[k]) - unshadowed[k]) <= 1e-9 * unshadowed[k];
    Rgb shadowed(0.0);
    double open = 0;
    if (agree && rule > 0) {
        shadowed = fourPointMean(values[3], values);
        open = rule;
    } else {
        // An opening's sky at the points: the patch's factor (its pattern through the
        // opening changes little across the patch, the shadows much), which cancels in the ratio.
        const Vec3 a = t[0], ab = t[1] - t[0], ac = t[2] - t[0];
        // Where it does change (skyFactorOver: nothing), each point takes the opening whole.
        const std::optional<double> sky = light.sky ? skyFactorOver(unshadowed, geometric) : 1.0;
        for (const auto& uv : refined) {
            Vec3 x = a + uv[0] * ab + uv[1] * ac;
            Random rng = pointRandom(x);
            if (sky) {
                shadowed += lights.fromOpeningWithSkyFactor(s, x, normal, vis, areaSamples, &rng, *sky);
                open += *sky * luminance(lights.unshadowedFromAreaSource(s, x, normal, false));
            } else {
                shadowed += lights.fromAreaSource(s, x, normal, vis, areaSamples, &rng);
                open += luminance(lights.unshadowedFromAreaSource(s, x, normal));
            }
        }
    }
    // The colour of the light (per channel) with the luminance of the exact mean.
    const Rgb colour = light.luminance / luminance(light.luminance);
    if (open <= 0) return colour * exact;  // no sample point sees the light: take it as unshadowed
    return shadowed * (exact / open);
}

/// True when an area source is equally visible (the same fraction of it) from the four
/// evaluation points, given its shadowed `values` and unshadowed `opens` there;
/// otherwise a shadow's edge crosses the patch and the 4-point rule cannot say how much
/// of the patch it darkens.
bool sameVisibleFraction(const Rgb* values, const Rgb* opens) {
    double lo = 1e300, hi = -1e300;
    for (int k = 0; k < 4; ++k) {
        const double open = luminance(opens[k]);
        const double fraction = open > 0 ? luminance(values[k]) / open : 1.0;
        lo = std::min(lo, fraction), hi = std::max(hi, fraction);
    }
    return hi - lo <= 1e-9;
}

/// Mean illuminance (lx) over patch p from area source s over the first `count` of the
/// `refined` points, for a patch that a shadow's edge crosses; an opening with the sky's
/// factor `sky` over the patch (patchSkyFactor), or taken whole at each point without one.
Rgb refinedAreaSourceMean(const PatchMesh& mesh, const Patch& p, const Vec3& normal, const DirectLight& lights,
                          size_t s, const Visibility& vis, int areaSamples,
                          const std::vector<std::array<double, 2>>& refined, size_t count, std::optional<double> sky) {
    const Vec3 a = mesh.corner(p, 0), ab = mesh.corner(p, 1) - a, ac = mesh.corner(p, 2) - a;
    count = std::min(count, refined.size());
    Rgb sum(0.0);
    for (size_t k = 0; k < count; ++k) {
        const Vec3 x = a + refined[k][0] * ab + refined[k][1] * ac;
        Random rng = pointRandom(x);
        sum += sky ? lights.fromOpeningWithSkyFactor(s, x, normal, vis, areaSamples, &rng, *sky)
                   : lights.fromAreaSource(s, x, normal, vis, areaSamples, &rng);
    }
    return sum / static_cast<double>(count);
}

/// What one side of a patch receives directly: the mean illuminance over it (lx), its
/// corners' values, and the flux mirrors absorbed on the way (lm per m² of the patch).
struct SideLight {
    Rgb mean{0.0};
    Rgb outdoorSun{0.0};  ///< lx of the mean: the sun from outdoors, not through an opening
    Rgb corner[3];
    Rgb mirrorLoss{0.0};
};

/// The direct light on the side of patch p that faces `normal` (p.normal for its front,
/// −p.normal for its back): the 4-point rule, with each point source's share made exact
/// and near area lights integrated adaptively. The rule's points: the centroid, and the
/// corners — the ones `corners` shares from it (none when null), the others pulled a hair
/// toward the centroid (so shadow rays do not start inside a neighbouring wall).
SideLight sideLight(const PatchMesh& mesh, const Patch& p, const Vec3& normal, const DirectLight& lights,
                    const Visibility& vis, int areaSamples, const std::vector<std::array<double, 2>>& refined,
                    CornerValues* corners, bool back = false) {
    thread_local PointValues own[4];
    const PointValues* at[4];
    for (int k = 0; k < 3; ++k) {
        const uint32_t v = p.v[k];
        if (corners && corners->shares(v)) {
            at[k] = &corners->at(mesh, v, glm::dot(normal, p.normal) < 0, normal, lights, vis, areaSamples);
        } else {
            evaluateAt(own[k], mesh.corner(p, k) + 1e-4 * (p.centroid - mesh.corner(p, k)), normal, lights, vis,
                       areaSamples);
            at[k] = &own[k];
        }
    }
    evaluateAt(own[3], p.centroid, normal, lights, vis, areaSamples);
    at[3] = &own[3];
    const std::array<Vec3, 4> points{at[0]->x, at[1]->x, at[2]->x, at[3]->x};
    const Rgb e[4] = {at[0]->e, at[1]->e, at[2]->e, at[3]->e};
    SideLight out;
    for (int k = 0; k < 3; ++k) out.corner[k] = e[k];
    out.mean = fourPointMean(e[3], e);
    const std::array<Vec3, 3> triangle{mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
    double strongest = 0;  // lx: the largest unshadowed 4-point mean of an area source
    for (size_t s = 0; s < lights.sourceCount(); ++s) {
        if (lights.isPointSource(s)) continue;
        const Rgb opens[4] = {at[0]->open[s], at[1]->open[s], at[2]->open[s], at[3]->open[s]};
        strongest = std::max(strongest, luminance(fourPointMean(opens[3], opens)));
    }
    for (size_t s = 0; s < lights.sourceCount(); ++s) {
        const Rgb values[4] = {at[0]->share[s], at[1]->share[s], at[2]->share[s], at[3]->share[s]};
        const Rgb opens[4] = {at[0]->open[s], at[1]->open[s], at[2]->open[s], at[3]->open[s]};
        const Rgb fourPoint = fourPointMean(values[3], values);
        const bool outdoorSun = static_cast<int>(s) == lights.sunSource() && !lights.sunThroughOpening(p.centroid);
        if (back && outdoorSun) {
            // The sun on the back of a one-sided surface from outdoors: the outside of the
            // building's shell, not light that came in.
            out.mean -= fourPoint;
            continue;
        }
        Rgb sourceMean = fourPoint;
        if (lights.isPointSource(s)) {
            // A virtual point light's reflected rim is sharp and may cross the patch
            // between the four points. (An area image's rim is in its unshadowed value,
            // which is clipped to the mirrors exactly, so the rule below follows it.)
            const ApertureCover cover = lights.apertureCover(s, triangle);
            if (cover == ApertureCover::None) {
                sourceMean = Rgb(0.0);
            } else {
                const bool partial = cover == ApertureCover::Partial;
                if (fourPoint == Rgb(0.0) && !partial) continue;
                sourceMean =
                    pointSourceMean(mesh, p, normal, lights, s, vis, points, values, fourPoint, refined, partial);
            }
        } else if (auto near = nearAreaSourceMean(mesh, p, normal, lights, s, vis, areaSamples, values, opens, points,
                                                  refined)) {
            sourceMean = *near;
        } else if (!sameVisibleFraction(values, opens)) {
            const double ofStrongest = strongest > 0 ? luminance(fourPointMean(opens[3], opens)) / strongest : 1.0;
            const auto count = static_cast<size_t>(std::clamp(std::lround(kShadowSamples * ofStrongest),
                                                              static_cast<long>(kMinAreaShadowSamples),
                                                              static_cast<long>(kShadowSamples)));
            sourceMean = refinedAreaSourceMean(mesh, p, normal, lights, s, vis, areaSamples, refined, count,
                                               patchSkyFactor(lights, s, normal, points, opens));
        }
        out.mean += sourceMean - fourPoint;
        if (outdoorSun) out.outdoorSun = sourceMean;
        out.mirrorLoss += mirrorLoss(sourceMean, lights.sourceWeight(s));
    }
    return out;
}

/// A corner under a solid standing on its patch (mesh.underSolid) lies inside the solid:
/// its own direct light is 0, and the near field of a gather, which takes the patch's part
/// in front of the solid linear between its corners, read that part dark toward the solid
/// (the foot of a box: ±20 % from one point to the next along it, at the 5 mm a seam's
/// vertex gather sits from it). The corner keeps the light at the outline instead, as its
/// indirect light does (contact_vertices.h): at the nearest point of the outlines crossing
/// the patch, a nudge in front of the standing surface. The patch's mean is not changed.
void lightCornersUnderSolids(const scene::Scene& scene, const PatchMesh& mesh, const DirectLight& lights,
                             const Visibility& vis, int areaSamples, RadiositySolution& solution) {
    if (mesh.underSolid.empty() || mesh.outlineBegin.empty()) return;
    const double nudge = pointNudge(scene);
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        if (mesh.outlineBegin[i] == mesh.outlineBegin[i + 1]) return;  // no outline crosses it
        const Patch& p = mesh.patches[i];
        thread_local PointValues at;
        for (int k = 0; k < 3; ++k) {
            if (!mesh.underSolid[p.v[k]]) continue;
            const auto point = inFrontOfOutline(mesh, mesh.corner(p, k), p.normal, {static_cast<uint32_t>(i)}, nudge);
            evaluateAt(at, *point, p.normal, lights, vis, areaSamples);  // crossed: an outline is there
            solution.directCorner[3 * i + k] = RgbF(at.e);
        }
    });
}

}  // namespace

void computeDirect(const scene::Scene& scene, const PatchMesh& mesh, const DirectLight& lights, const Visibility& vis,
                   int areaSamples, RadiositySolution& solution, const std::function<void(double)>& onProgress) {
    solution.emittedFlux = lights.emittedFlux();
    solution.directMean.assign(mesh.patches.size(), Rgb(0.0));
    solution.directCorner.assign(3 * mesh.patches.size(), RgbF(0.0f));
    std::vector<double> mirrorAbsorbed(mesh.patches.size(), 0.0);  // lm, per patch
    std::vector<double> backReceived(mesh.patches.size(), 0.0);    // lm, per patch
    std::vector<double> outdoorSun(mesh.patches.size(), 0.0);      // lm, per patch
    const auto refined = shadowSamplePoints(kShadowSamples);
    const std::vector<char> shared = sharedCorners(mesh);
    const std::vector<char> sealed = sealedGroups(scene);  // their backs face a solid's dark inside
    std::atomic<size_t> done{0};
    const size_t n = mesh.patches.size();
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, n, kChunkPatches),
        [&](const tbb::blocked_range<size_t>& chunk) {
            thread_local CornerValues corners;
            corners.start(shared);
            for (size_t i = chunk.begin(); i != chunk.end(); ++i) {
                const Patch& p = mesh.patches[i];
                const SideLight front = sideLight(mesh, p, p.normal, lights, vis, areaSamples, refined, &corners);
                for (int k = 0; k < 3; ++k) solution.directCorner[3 * i + k] = RgbF(front.corner[k]);
                solution.directMean[i] = front.mean;
                outdoorSun[i] = luminance(front.outdoorSun) * p.area;
                mirrorAbsorbed[i] = luminance(front.mirrorLoss) * p.area;
                // The back of a one-sided surface is the inside of a solid: light that still
                // reaches it (through a gap, onto a blind lit from behind) is absorbed there, and
                // booked. A two-sided surface's back is a patch of its own, and a back covered by
                // another surface's front (back-to-back quads) receives nothing: that surface does;
                // nor does the inside of a sealed solid (sealed_solids.h).
                if (!scene.materials[p.material].twoSided && !sealed[p.group] &&
                    !vis.backCovered(p.centroid, p.normal)) {
                    const SideLight back =
                        sideLight(mesh, p, -p.normal, lights, vis, areaSamples, refined, &corners, true);
                    backReceived[i] = luminance(back.mean) * p.area;
                    mirrorAbsorbed[i] += luminance(back.mirrorLoss) * p.area;
                }
            }
            if (onProgress) onProgress(static_cast<double>(done += chunk.size()) / n);
        },
        tbb::simple_partitioner());
    lightCornersUnderSolids(scene, mesh, lights, vis, areaSamples, solution);
    // Mirrors have no patches (their front passes light on by the image method), but
    // their backs absorb what reaches them, e.g. through the gap between a mirror and
    // the wall it hangs on.
    const PatchMesh mirrorBacks = meshMirrorBacks(scene, scene.meshing);
    std::vector<double> mirrorBackReceived(mirrorBacks.patches.size(), 0.0);  // lm, per triangle
    std::vector<double> mirrorBackLoss(mirrorBacks.patches.size(), 0.0);      // lm, per triangle
    tbb::parallel_for(size_t(0), mirrorBacks.patches.size(), [&](size_t i) {
        const Patch& p = mirrorBacks.patches[i];
        const SideLight back =
            sideLight(mirrorBacks, p, p.normal, lights, vis, areaSamples, refined, nullptr);  // few: not shared
        mirrorBackReceived[i] = luminance(back.mean) * p.area;
        mirrorBackLoss[i] = luminance(back.mirrorLoss) * p.area;
    });

    // Sums in a fixed order (deterministic).
    solution.mirrorAbsorbedDirect = 0;
    for (double f : mirrorAbsorbed) solution.mirrorAbsorbedDirect += f;
    for (double f : mirrorBackLoss) solution.mirrorAbsorbedDirect += f;
    solution.backFlux.assign(scene.groups.size(), 0.0);
    for (size_t i = 0; i < mesh.patches.size(); ++i) solution.backFlux[mesh.patches[i].group] += backReceived[i];
    for (size_t i = 0; i < mirrorBacks.patches.size(); ++i)
        solution.backFlux[mirrorBacks.patches[i].group] += mirrorBackReceived[i];
    solution.outdoorDirect = 0;
    for (double f : outdoorSun) solution.outdoorDirect += f;
    solution.backAbsorbedDirect = 0;
    for (double f : solution.backFlux) solution.backAbsorbedDirect += f;
}

}  // namespace rayrad::radiosity
