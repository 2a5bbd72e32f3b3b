// Direct light from the primary sources (point, spot, area) at any surface point.
#pragma once

#include <core/math.h>
#include <core/random.h>
#include <core/visibility.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/mirrors/mirror_images.h>
#include <scene/scene.h>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace rayrad::radiosity {

/// An emissive input polygon (front side emits uniformly, Lambertian).
struct AreaLight {
    std::vector<Vec3> vertices;
    Vec3 normal{0.0};
    double area = 0;                             ///< m²
    Rgb luminance{0.0};                          ///< cd/m² per channel
    std::vector<std::array<Vec3, 3>> triangles;  ///< for sampling
    std::vector<double> triangleAreas;
    Vec3 centre{0.0};        ///< mean of the vertices
    double radius = 0;       ///< largest vertex distance from the centre, m
    PolygonMoments moments;  ///< area centroid and second moment, for far form factors
    /// An opening: the sky seen through it, L(ω) τ(θ) along each direction ω through it
    /// (θ its angle with the normal), and `luminance` the mean, Φ_in / (π A), that the
    /// ranking and the energy account use; null for a lamp.
    const scene::Daylight* sky = nullptr;
    double transmittance = 1;  ///< the opening's glazing at normal incidence (1: none)
    /// An opening's mirror image: the direction beyond the real opening of a ray that
    /// reaches the image along w is skyFrame · w (the reflections undone), and the mirrors
    /// pass skyWeight (Y of Π Ks) of its light. The identity and 1 for a real opening.
    glm::dmat3 skyFrame{1.0};
    double skyWeight = 1;
    /// The luminance (cd/m²) that comes through toward a receiver along the unit direction
    /// w (from the receiver through the opening): the sky's (or ground's), × the glazing's τ
    /// (× skyWeight).
    double skyLuminanceAlong(const Vec3& w) const;
};

/// An area light from its outline (CCW seen from its emitting front).
AreaLight makeAreaLight(std::vector<Vec3> vertices, const Vec3& normal, const Rgb& luminance);

/// The illuminance (lx) that comes in through an opening of unit normal `inward` (facing
/// the room) from the unobstructed sky and ground: ∫ L(ω) τ(θ) cosθ dω over the outside
/// half of the sphere. The opening's sky flux is this × its area.
double enteringIlluminance(const scene::Daylight& daylight, const Vec3& inward, double transmittance);

/// F(dA_x → light), unoccluded: Lambert's formula within 5 of the light's diameters, or
/// when x's horizon cuts the light; beyond, the second-order far form factor
/// (form_factor.h: within 10⁻⁴ of A/(π r²) there), a fraction of the cost.
double areaLightFormFactor(const AreaLight& light, const Vec3& x, const Vec3& n);

/// How the mirror polygons of a virtual point light's chain let it onto a triangle,
/// ignoring occluders: onto none of it, all of it, or perhaps some of it.
enum class ApertureCover { None, Whole, Partial };

/// What adaptive shadow testing found at one primary hit of a pixel, for the pixel's other
/// samples that land on the same patch (within the pixel's footprint): the far area lights
/// it tested with the visible fraction their rays found, and its estimate for the untested
/// lights. Those samples test the near area lights and the point lights again (their
/// shadows can be sharp within a pixel) and take each far light's F at their own point
/// times the fraction found here: a far light's soft shadow is traced once per pixel and
/// patch instead of at every sample. Images (mirrors) are tested at every sample.
/// A far light's F at another sample is its point approximation there, A cosθ_x cosθ_y /
/// (π r²), times the ratio F / point approximation found at the first: beyond five
/// diameters that ratio is 1 + O((size / r)²) and changes across a pixel by a further
/// factor footprint / r, and the second-order F (form_factor.h) costs several times more.
struct PixelLightMemo {
    /// A far area light (numbered as `retested`) and what its point approximation at
    /// another sample is multiplied by: visible fraction × F / point approximation, both
    /// at the first sample.
    struct Far {
        uint32_t light;
        double scale;
    };
    int64_t patch = -1;              ///< the patch of the hit that filled it; −1: empty (a new pixel)
    std::vector<uint32_t> retested;  ///< lights tested at every sample: points first, then area lights
    std::vector<Far> far;
    Rgb untested{0.0};  ///< lx: the untested lights' estimate
};

/// Evaluates E_direct(x, n) in lx from every primary light, with shadow rays, and from
/// their images in the scene's mirrors (virtual lights: the light mirrored along each
/// chain, × Π Ks, seen only through the mirror polygons).
class DirectLight {
  public:
    explicit DirectLight(const scene::Scene& scene);

    /// Illuminance (lx, RGB) on a surface at x with unit normal n.
    /// Point/spot: E = I(ω) cosθ / d² · V. Area: E = π L F_analytic · (visible fraction),
    /// the fraction estimated from `samples` stratified shadow rays per light, weighted by
    /// cosθ_x cosθ_y / r²; `rng` jitters them (nullptr: cell centres, deterministic).
    /// `perSource` (if given, size sourceCount()) also gets each source's share of the
    /// result, and `perSourceOpen` (if given) each area source's unshadowed π L F (to the
    /// part of an image seen through the mirrors; 0 for point sources), from the same
    /// evaluation.
    Rgb illuminance(const Vec3& x, const Vec3& n, const Visibility& vis, int samples, Random* rng,
                    std::vector<Rgb>* perSource = nullptr, std::vector<Rgb>* perSourceOpen = nullptr) const;

    /// The same for display (the ray tracer), with adaptive shadow testing (Ward 1991):
    /// the real lights are ranked by their unshadowed illuminance and shadow-tested in that
    /// order until the untested ones could add less than `threshold` × all that x receives
    /// (what the tested ones gave plus `received`, lx: Y of the indirect illuminance there);
    /// those are added unshadowed × the tested ones' visible share. Images are always
    /// tested. threshold 0: every light tested, as illuminance(). See shadow_testing.cpp.
    /// `pixel` (or null): the pixel's memo, and `patch` the hit's patch: when the memo holds
    /// the same patch the far lights are taken from it, else it is filled from this hit.
    Rgb illuminanceForDisplay(const Vec3& x, const Vec3& n, const Visibility& vis, int samples, Random* rng,
                              double threshold, double received = 0, PixelLightMemo* pixel = nullptr,
                              int64_t patch = -1) const;

    /// Sources: for the real scene and then each mirror image, the point lights and then
    /// the area lights: s = chain · (points + areas) + k, chain 0 the real scene.
    size_t sourceCount() const { return perChain() * (1 + m_images.size()); }
    bool isPointSource(size_t s) const { return s % perChain() < m_pointLights.size(); }
    /// Where point source s is (for an image, the mirrored position), m.
    Vec3 pointSourcePosition(size_t s) const;
    /// Π Ks of the mirrors on source s's path (1 for a real light): of the light it
    /// delivers, a fraction 1/weight − 1 more was absorbed by the mirrors on the way.
    Rgb sourceWeight(size_t s) const { return s < perChain() ? Rgb(1.0) : m_images[s / perChain() - 1].weight; }
    /// The intensity (cd, RGB; × Π Ks for an image) point source s sends toward the point
    /// x, along the straight (for an image: unfolded) path, ignoring occluders and apertures.
    Rgb pointSourceIntensityToward(size_t s, const Vec3& x) const;
    /// True when x is in the near field of real point source s: a luminaire's light then
    /// leaves from its whole opening (images stay point sources).
    bool inNearFieldOf(size_t s, const Vec3& x) const { return s < perChain() && inNearField(m_pointLights[s], x); }
    /// The points point source s's light leaves from as seen from x: a luminaire's
    /// opening's parts when x is within `sizes` times the opening's size, else its position.
    std::vector<Vec3> emissionPoints(size_t s, const Vec3& x, double sizes = scene::kNearFieldSizes) const {
        if (s < perChain() && inNearField(m_pointLights[s], x, sizes)) return m_pointLights[s].openingPoints;
        return {pointSourcePosition(s)};
    }
    /// The intensity (cd, RGB; × Π Ks for an image) point source s sends along the unit
    /// direction w (for an image: the unfolded direction), one part's share in the near field
    /// being this / the number of parts.
    Rgb pointSourceIntensityAlong(size_t s, const Vec3& w) const;
    /// x within `sizes` times l's opening's size of it (l a luminaire with an opening).
    static bool inNearField(const scene::PointLight& l, const Vec3& x, double sizes = scene::kNearFieldSizes);
    /// True when point source s sends the same intensity every way (a point light).
    bool isIsotropic(size_t s) const {
        const scene::PointLight& l = m_pointLights[s % perChain()];
        return !l.isSpot && !l.photometry;
    }
    /// Illuminance (lx) at x, normal n, from point source s alone, with its shadow ray.
    Rgb fromPointSource(size_t s, const Vec3& x, const Vec3& n, const Visibility& vis) const;

    /// Area source s (not a point source): the real polygon or its image, luminance × Π Ks.
    const AreaLight& areaSource(size_t s) const;
    /// Illuminance (lx) at x, normal n, from area source s alone: π L F · visible fraction
    /// from `samples` shadow rays (through the mirror chain for an image).
    Rgb fromAreaSource(size_t s, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                       Random* rng = nullptr) const;
    /// Opening s's illuminance (lx) at x, with the sky's luminance through it taken as
    /// `skyFactor` times its mean (the factor at a point nearby: skyFactorAt), only its
    /// shadows sampled: π L̄ F · skyFactor · visible fraction. Across a patch the sky seen
    /// through an opening changes little and its shadows much; at each of the many points
    /// a shadow's edge asks for, this costs a lamp's rays instead of the opening's pieces.
    /// Any other source: fromAreaSource.
    Rgb fromOpeningWithSkyFactor(size_t s, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                                 Random* rng, double skyFactor) const;
    /// The same without shadows: π L F, F the analytic form factor (to the part of an
    /// image that x sees through the mirror polygons). For an opening the sky's luminance
    /// through it (throughOpening), or with `withSky` false its mean: π L̄ F, which changes
    /// across a receiver as F does and costs one form factor.
    Rgb unshadowedFromAreaSource(size_t s, const Vec3& x, const Vec3& n, bool withSky = true) const;
    /// For point source s: Whole when it is a real light, or when its image sees every
    /// corner of triangle t through its mirror chain (the set of receivers that see it
    /// is convex, so then all of t does). None when t lies behind the chain's last
    /// mirror, or beyond the plane through one of its edges and the image. Else Partial:
    /// the rim of the reflected light may cross t, and four sample points cannot say how
    /// much of t it lights.
    ApertureCover apertureCover(size_t s, const std::array<Vec3, 3>& t) const;

    const std::vector<AreaLight>& areaLights() const { return m_areaLights; }
    const std::vector<scene::PointLight>& pointLights() const { return m_pointLights; }
    /// Total flux in lm emitted by all primary lights (luminance-weighted); for daylight,
    /// what enters through the openings from the unobstructed sky, ground and sun.
    double emittedFlux() const;
    /// Measures what actually comes in through the openings, with the scene's geometry
    /// outside them (frames, overhangs, the wall around a hole smaller than the opening):
    /// per opening, rays outward from 8 × 8 points on each of its triangles in 16 × 32
    /// cosine-distributed directions (and toward the sun), Φ = A ∫ L τ cosθ V dω. From then
    /// on emittedFlux() counts it instead of the unobstructed sky's. The same rays continued
    /// inward measure passingThrough().
    void measureEntering(const Visibility& vis);
    /// lm of what comes in through the openings that meets no surface and leaves again
    /// through an opening (from one window straight out of another), measured with it.
    double passingThrough() const { return m_passingThrough; }
    /// The sun as a point source (its index), or −1 without direct sun.
    int sunSource() const { return m_sun; }
    /// The product of the glazings' transmittances τ(θ) the ray from x along the unit
    /// direction w crosses (each opening it crosses, to the first `maxDistance` m).
    double openingTransmittance(const Vec3& x, const Vec3& w, double maxDistance) const {
        if (!m_anyGlazing) return 1.0;  // open holes pass everything: no need to look
        double tau = 1;
        openingsCrossed(x, w, maxDistance, &tau);
        return tau;
    }
    /// How many openings the ray from x along the unit direction w crosses within
    /// `maxDistance` m; `tau` (if given) is multiplied by their glazings' τ(θ).
    int openingsCrossed(const Vec3& x, const Vec3& w, double maxDistance, double* tau = nullptr) const;
    /// The openings the daylight enters through.
    size_t openingCount() const { return m_openings.size(); }
    /// F from x (unit normal n) to opening k, times the fraction of it x sees past occluders
    /// (`samples` shadow rays; cell centres): where light leaving x goes out of the room.
    double openingFormFactor(size_t k, const Vec3& x, const Vec3& n, const Visibility& vis, int samples) const;
    /// Whether the sun reaches x through an opening (not from outdoors, onto the building's shell).
    bool sunThroughOpening(const Vec3& x) const {
        return m_sun >= 0 && openingsCrossed(x, m_daylight->sunDirection, m_beyondScene) > 0;
    }
    size_t imageCount() const { return m_images.size(); }
    size_t virtualLightCount() const { return m_images.size() * (m_pointLights.size() + m_areaLights.size()); }

  private:
    size_t perChain() const { return m_pointLights.size() + m_areaLights.size(); }
    /// E = I(ω) cosθ / d² without the shadow ray.
    /// Point and spot lights, and luminaires beyond their near field: E = I(ω) cosθ / d²
    /// from the position. A luminaire within kNearFieldSizes of its opening's size: the
    /// mean over its opening's parts (each with its own shadow ray in fromPointLight).
    Rgb unshadowedFromPointLight(const scene::PointLight& l, const Vec3& x, const Vec3& n) const;
    Rgb fromPointLight(const scene::PointLight& l, const Vec3& x, const Vec3& n, const Visibility& vis) const;
    /// The sun's glazing factor at x (1 for other lights and unglazed openings).
    double glazingFor(const scene::PointLight& l, const Vec3& x) const;
    static Rgb fromPointImage(const scene::PointLight& l, const MirrorImage& image, const MirrorPath& path,
                              const Vec3& x, const Vec3& n);
    /// `open` (if given) gets the unshadowed value π L F, `visible` the visible fraction
    /// its rays found (0 when the light is below x's horizon).
    Rgb fromAreaLight(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                      Random* rng, Rgb* open = nullptr, double* visible = nullptr) const;
    /// The fraction of an area light x sees past occluders (`samples` stratified shadow
    /// rays, fewer for a far light), weighted by the unoccluded integrand cosθ_x cosθ_y / r²,
    /// for an opening also by the sky's luminance through it.
    double visibleFraction(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility* vis, int samples,
                           Random* rng) const;
    /// An opening's light at x (lx): its outline cut into about `samples` parts, split
    /// further into pieces near x, each piece delivering π F_c L(ω_c) τ(θ_c) (F_c its form
    /// factor, ω_c the direction to its centroid). One shadow ray per part, continued through
    /// a point of one of its pieces (chosen in proportion to their light) beyond the scene,
    /// says whether the part's light arrives. `open` gets the unshadowed sum; `vis` null:
    /// nothing occludes.
    double throughOpening(const AreaLight& light, const Vec3& x, const Vec3& n, const Visibility* vis, int samples,
                          Random* rng, double* open) const;
    /// Area light k's image i: the part of it x sees through the chain's mirror polygons
    /// (exact for convex mirrors, so the rim of a reflected light is not left to shadow
    /// rays), with its shadow rays through the chain.
    Rgb fromAreaImage(size_t i, size_t k, const Vec3& x, const Vec3& n, const MirrorPath& path, int samples,
                      Random* rng, Rgb* open = nullptr) const;
    std::optional<AreaLight> visiblePartOfImage(size_t i, size_t k, const Vec3& x) const;
    /// illuminanceForDisplay at another sample of the pixel on the memo's patch.
    Rgb fromPixelMemo(const PixelLightMemo& pixel, const Vec3& x, const Vec3& n, const Visibility& vis, int samples,
                      Random* rng) const;
    /// The light of every image (virtual lights) at x; `perSource`/`perSourceOpen` as for
    /// illuminance().
    Rgb fromImages(const Vec3& x, const Vec3& n, const Visibility& vis, int samples, Random* rng,
                   std::vector<Rgb>* perSource, std::vector<Rgb>* perSourceOpen) const;

    std::vector<scene::PointLight> m_pointLights;
    std::vector<AreaLight> m_areaLights;
    int m_sun = -1;                                 ///< the sun's index in m_pointLights
    std::shared_ptr<const scene::Daylight> m_daylight;  ///< the sky the openings point to
    std::vector<size_t> m_openings;                 ///< the openings' indices in m_areaLights
    double m_beyondScene = 0;                       ///< m: a distance that leaves the scene from anywhere in it
    std::optional<double> m_enteringMeasured;       ///< lm through the openings, measured (sky, ground and sun)
    double m_passingThrough = 0;                    ///< lm of it that leaves again untouched
    bool m_anyGlazing = false;                      ///< some opening is glazed (transmittance < 1)
    std::vector<scene::Mirror> m_mirrors;
    bool m_convexMirrors = true;  ///< every mirror polygon convex: images are clipped exactly
    std::vector<MirrorImage> m_images;
    /// m_imageAreaLights[i][k]: area light k mirrored along image i, luminance × Π Ks.
    std::vector<std::vector<AreaLight>> m_imageAreaLights;
};

}  // namespace rayrad::radiosity
