// The image method for planar mirrors: chains of reflections and the paths through them.
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters.h>
#include <radiosity/patch_mesh.h>
#include <scene/scene.h>

#include <glm/mat4x4.hpp>

#include <memory>

#include <vector>

namespace rayrad::radiosity {

/// One image of the scene: a chain of mirrors (the first reflection first). A point p
/// has the image transform·p; light from the image reaches a receiver only through the
/// chain's mirror polygons, last mirror first, carrying the product of their Ks.
struct MirrorImage {
    std::vector<int> chain;      ///< indices into Scene::mirrors
    glm::dmat4 transform{1.0};   ///< world → image (a product of reflections)
    Rgb weight{1.0};             ///< Π Ks along the chain
    Vec3 point(const Vec3& p) const { return Vec3(transform * glm::dvec4(p, 1.0)); }
    Vec3 direction(const Vec3& d) const { return Vec3(transform * glm::dvec4(d, 0.0)); }
    /// An odd number of reflections turns a counter-clockwise polygon clockwise.
    bool reversesWinding() const { return chain.size() % 2 == 1; }
};

/// How far images of images go.
struct MirrorLimits {
    int maxDepth = 4;          ///< reflections per chain
    double minWeight = 1e-3;   ///< drop a chain once Y(Π Ks) falls below this
};

/// Every chain up to the limits: no mirror twice in a row, and each next mirror must
/// have part of its polygon in front of the previous one (and the previous in front of
/// it), so the light can travel between them. Two facing mirrors give two chains per
/// depth, so the count is bounded by the depth and by the weight. `truncated` (if given)
/// tells whether a limit cut a chain light could follow: then some light reflected more
/// often is not modelled, and the chains do not account for all the light a mirror gets.
std::vector<MirrorImage> enumerateMirrorImages(const std::vector<scene::Mirror>& mirrors, const MirrorLimits& limits,
                                               bool* truncated = nullptr);

/// The images the scene's settings ask for: none when mirrors are ignored.
std::vector<MirrorImage> mirrorImagesFor(const scene::Scene& scene, bool* truncated = nullptr);

/// The patches and clusters as seen in one image: positions, normals and centroids
/// mirrored, each triangle's winding reversed after an odd number of reflections so
/// its front stays its front, cluster
/// voxels recomputed on the real grid (they may lie outside it). Same indices as the
/// real mesh and clustering, so light values index both.
struct MirroredGeometry {
    PatchMesh mesh;
    Clustering clustering;
};
MirroredGeometry mirrorGeometry(const PatchMesh& mesh, const Clustering& clustering, const MirrorImage& image);

class MirrorPath;

/// The part of polygon `source` (in the image's space, behind the chain's last mirror)
/// that a receiver at x sees through every mirror polygon of the chain, ignoring
/// occluders: `source` clipped to the cone from x through each mirror (unfolded into the
/// image's space as x sees it) and to the mirror's back. Empty when x sees none of it.
/// The mirror polygons must be convex (isConvexAround); the cone of a convex polygon is
/// the intersection of the half spaces through x and each of its edges.
std::vector<Vec3> clipToApertures(const std::vector<scene::Mirror>& mirrors, const MirrorImage& image,
                                  std::vector<Vec3> source, const Vec3& x);

/// The unfolded path from a receiver to an image point through the chain's mirror
/// polygons, ignoring occluders: false unless the segment toward each successive image
/// crosses its mirror inside the polygon, from the front. `hits` (if given) gets the
/// crossing points, last mirror of the chain first, then the real source's position.
bool throughApertures(const std::vector<scene::Mirror>& mirrors, const MirrorImage& image, const Vec3& imagePoint,
                      const Vec3& receiver, std::vector<Vec3>* hits = nullptr);

/// One image of the scene ready for transfers: the chain, the mirrored patches and
/// clusters, and visibility through the chain (which refers to `image`, so views are
/// held by pointer and never move).
struct MirrorView {
    MirrorImage image;
    MirroredGeometry geometry;
    std::unique_ptr<MirrorPath> path;
};
/// `truncated` as for enumerateMirrorImages().
std::vector<std::unique_ptr<MirrorView>> mirrorViewsFor(const scene::Scene& scene, const PatchMesh& mesh,
                                                        const Clustering& clustering, const Visibility& vis,
                                                        bool* truncated = nullptr);

/// Visibility through a mirror chain, as an adaptor of the scene's: `visible(a, b)` is
/// true when one end is an image point (behind the last mirror) and the other a real
/// receiver, the unfolded segment between them crosses every mirror polygon of the
/// chain in order (last mirror first), and every real leg of the path is unoccluded.
/// Built per query; holds references only.
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
