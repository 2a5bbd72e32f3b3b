// The image method for planar mirrors: chains of reflections and the paths through them.
#pragma once

#include <core/visibility.h>
#include <radiosity/mesh/patch_mesh.h>
#include <scene/scene.h>

#include <glm/mat4x4.hpp>

#include <memory>

#include <vector>

namespace rayrad::radiosity {

/// One image of the scene: a chain of mirrors (the first reflection first). A point p
/// has the image transform·p; light from the image reaches a receiver only through the
/// chain's mirror polygons, last mirror first, carrying the product of their Ks.
struct MirrorImage {
    std::vector<int> chain;  ///< indices into Scene::mirrors
    /// Mirror chain[k] as a receiver sees it, reflected in every later mirror of the
    /// chain (R_{n−1} ∘ … ∘ R_{k+1}), last mirror first: the straight (unfolded) path
    /// from a receiver to an image point crosses each.
    struct Aperture {
        std::vector<Vec3> polygon;
        Vec3 normal;    ///< unit, the mirror's front
        Vec3 centre;    ///< of the polygon's vertices
        double radius;  ///< largest distance of a vertex from the centre, m
        /// Per edge i (polygon[i] → polygon[i+1]), the unit normal in the plane pointing
        /// out of the polygon; empty when the polygon is not convex.
        std::vector<Vec3> outward;
        Aperture(std::vector<Vec3> polygon, const Vec3& normal);
    };
    std::vector<Aperture> apertures;
    glm::dmat4 transform{1.0};  ///< world → image (a product of reflections)
    Rgb weight{1.0};            ///< Π Ks along the chain
    /// An estimate of the chain's étendue, m² sr: ∫∫ cosθ cosθ' / r² over the rays that
    /// cross every aperture, bounded by the smallest étendue of two of its apertures
    /// (π A for a single mirror). Light of luminance L carries at most L·G through it.
    double etendue = 0;
    Vec3 point(const Vec3& p) const { return Vec3(transform * glm::dvec4(p, 1.0)); }
    Vec3 direction(const Vec3& d) const { return Vec3(transform * glm::dvec4(d, 0.0)); }
    /// An odd number of reflections turns a counter-clockwise polygon clockwise.
    bool reversesWinding() const { return chain.size() % 2 == 1; }
    /// False when no segment from a point within `imageRadius` of `imageCentre` (image
    /// space) to one within `receiverRadius` of `receiver` crosses every aperture: then
    /// no light passes between the two balls through the chain, whatever the occluders.
    /// A segment between the balls stays within max(radii) of the segment between the
    /// centres, so that distance to each aperture decides. Cheap: the chain's length
    /// times its polygons' edges.
    bool mayPass(const Vec3& imageCentre, double imageRadius, const Vec3& receiver, double receiverRadius) const;
    /// The same for a receiver point x, tighter: the segments from x to the ball (centre c,
    /// radius R) fill the cone from x of half-angle α, sin α = R / |c − x|, so where the
    /// axis crosses an aperture's plane at X, at a distance s from x and an angle θ with
    /// the plane, every one of them crosses within s sin α / sin(θ − α) of X (the far end
    /// of the cone's section) — a mirror close to x lets through only what lines up with
    /// it. A ball wholly on x's side of an aperture's plane gets no segment across it.
    bool mayPassToPoint(const Vec3& imageCentre, double imageRadius, const Vec3& receiver) const;
};

/// How far images of images go.
struct MirrorLimits {
    int maxDepth = 4;         ///< reflections per chain
    double minWeight = 1e-3;  ///< drop a chain once Y(Π Ks) falls below this
    /// Drop a chain once Y(Π Ks) G / (π A) falls below this: the share of a uniformly
    /// bright room's light (luminance L̄ everywhere: π L̄ A leaves the surfaces) it can
    /// carry. 0 keeps every chain.
    double minShare = 0;
    double surfaceArea = 0;  ///< A, m² (the scene's surfaces)
};

/// Every chain up to the limits (depth, weight, étendue share): no mirror twice in a
/// row, and each next mirror must have part of its polygon in front of the previous one
/// (and the previous in front of it), so the light can travel between them. Two facing mirrors give two chains per
/// depth, so the count is bounded by the depth and by the weight. `truncated` (if given)
/// tells whether a limit cut a chain light could follow: then some light reflected more
/// often is not modelled, and the chains do not account for all the light a mirror gets.
std::vector<MirrorImage> enumerateMirrorImages(const std::vector<scene::Mirror>& mirrors, const MirrorLimits& limits,
                                               bool* truncated = nullptr);

/// The images the scene's settings ask for: none when mirrors are ignored.
std::vector<MirrorImage> mirrorImagesFor(const scene::Scene& scene, bool* truncated = nullptr);

/// One patch as an image shows it, mirrored on demand (images hold no copy of the
/// mesh): corners counter-clockwise from its front (an odd number of reflections swaps
/// two, so its front stays its front), normal, centroid, area and diameter from them.
/// `patch.v` keeps the real vertex indices.
struct ImagePatch {
    Patch patch;
    std::array<Vec3, 3> corners;
};
ImagePatch imagePatch(const PatchMesh& mesh, const Patch& p, const MirrorImage& image);

class MirrorPath;

/// The part of polygon `source` (in the image's space, behind the chain's last mirror)
/// that a receiver at x sees through every mirror polygon of the chain, ignoring
/// occluders: `source` clipped to the cone from x through each mirror (unfolded into the
/// image's space as x sees it) and to the mirror's back. Empty when x sees none of it.
/// The mirror polygons must be convex (isConvexAround); the cone of a convex polygon is
/// the intersection of the half spaces through x and each of its edges.
std::vector<Vec3> clipToApertures(const MirrorImage& image, std::vector<Vec3> source, const Vec3& x);

/// The unfolded path from a receiver to an image point through the chain's mirror
/// polygons, ignoring occluders: false unless the segment toward each successive image
/// crosses its mirror inside the polygon, from the front. `hits` (if given) gets the
/// crossing points, last mirror of the chain first, then the real source's position.
bool throughApertures(const std::vector<scene::Mirror>& mirrors, const MirrorImage& image, const Vec3& imagePoint,
                      const Vec3& receiver, std::vector<Vec3>* hits = nullptr);

/// One image of the scene ready for transfers: the chain and visibility through it
/// (which refers to `image`, so views are held by pointer and never move). Its patches
/// and clusters are mirrored when used (imagePatch, imageCluster): memory per image is
/// O(chain length), not O(patches).
struct MirrorView {
    MirrorImage image;
    std::unique_ptr<MirrorPath> path;
};
/// `truncated` as for enumerateMirrorImages().
std::vector<std::unique_ptr<MirrorView>> mirrorViewsFor(const scene::Scene& scene, const Visibility& vis,
                                                        bool* truncated = nullptr);

/// Visibility through a mirror chain, as an adaptor of the scene's: `visible(a, b)` is
/// true when one end is an image point (behind the last mirror) and the other a real
/// receiver, the unfolded segment between them crosses every mirror polygon of the
/// chain in order (last mirror first), and every real leg of the path is unoccluded.
/// Holds references only.
class MirrorPath final : public Visibility {
  public:
    MirrorPath(const std::vector<scene::Mirror>& mirrors, const MirrorImage& image, const Visibility& scene)
        : m_mirrors(mirrors), m_image(image), m_scene(scene) {}

    bool visible(const Vec3& from, const Vec3& to) const override;
    /// `x` a real receiver on a surface of normal n, `to` an image point.
    bool visibleFromSurface(const Vec3& x, const Vec3& n, const Vec3& to) const override;
    /// The same for a known image point and receiver; on success `leaving` (if given) is
    /// the unit direction in which the light left the real source (for spotlights).
    /// `receiverNormal` (if given): the receiver is a surface point (see Visibility).
    bool trace(const Vec3& imagePoint, const Vec3& receiver, Vec3* leaving = nullptr,
               const Vec3* receiverNormal = nullptr) const;

  private:
    const std::vector<scene::Mirror>& m_mirrors;
    const MirrorImage& m_image;
    const Visibility& m_scene;
};

}  // namespace rayrad::radiosity
