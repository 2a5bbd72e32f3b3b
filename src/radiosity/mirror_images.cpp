#include <radiosity/mirror_images.h>

#include <scene/polygon.h>

#include <cmath>

namespace rayrad::radiosity {

namespace {

/// The reflection across the plane n·x = offset as a 4×4 matrix: x − 2 (n·x − offset) n.
glm::dmat4 reflection(const scene::Mirror& m) {
    glm::dmat4 r(1.0);
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row) r[c][row] -= 2.0 * m.normal[row] * m.normal[c];
    for (int row = 0; row < 3; ++row) r[3][row] = 2.0 * m.offset * m.normal[row];
    return r;
}

/// True when some vertex of b lies strictly in front of a's plane.
bool partlyInFront(const scene::Mirror& a, const scene::Mirror& b) {
    double scale = 0;
    for (const auto& p : a.polygon) scale = std::max(scale, glm::length(p - a.polygon[0]));
    for (const auto& p : b.polygon)
        if (a.side(p) > 1e-9 * scale) return true;
    return false;
}

/// False when no light that reached mirror b from mirror a can go on to mirror c: some
/// plane has a's image in b on its back (≤ 0), b on its front (≥ 0) and c on its back.
/// A ray from a's image through b only moves further to the plane's front beyond b, so
/// it cannot reach c (a 90° corner: light that met a and then b cannot meet a again,
/// so the corner has 3 images, not a chain per depth). The planes tried are those of
/// a's image, b and c, each way round.
bool lightCanContinue(const scene::Mirror& a, const scene::Mirror& b, const scene::Mirror& c) {
    std::vector<Vec3> aImage;
    for (const auto& p : a.polygon) aImage.push_back(b.reflectPoint(p));
    double scale = 0;
    const std::vector<Vec3>* polygons[] = {&aImage, &b.polygon, &c.polygon};
    for (const auto* poly : polygons)
        for (const auto& p : *poly) scale = std::max(scale, glm::length(p - b.polygon[0]));
    const double eps = 1e-9 * (1 + scale);
    auto allOnSide = [eps](const std::vector<Vec3>& poly, const Vec3& n, double offset, double sign) {
        for (const auto& p : poly)
            if (sign * (glm::dot(n, p) - offset) > eps) return false;
        return true;
    };
    const Vec3 aImageNormal = scene::polygonNormal(aImage);
    const std::pair<Vec3, Vec3> planes[] = {{aImageNormal, aImage[0]}, {b.normal, b.polygon[0]}, {c.normal, c.polygon[0]}};
    for (const auto& [normal, point] : planes)
        for (double orientation : {1.0, -1.0}) {
            Vec3 n = orientation * normal;
            double offset = glm::dot(n, point);
            // a's image behind, b in front, c behind: the light cannot get from b to c.
            if (allOnSide(aImage, n, offset, 1.0) && allOnSide(b.polygon, n, offset, -1.0) &&
                allOnSide(c.polygon, n, offset, 1.0))
                return false;
        }
    return true;
}

/// Appends the chains that extend `image`; `truncated` is set when a chain that light
/// could follow was cut by the depth or the weight limit.
void extend(const std::vector<scene::Mirror>& mirrors, const MirrorLimits& limits, const MirrorImage& image,
            std::vector<MirrorImage>& out, bool& truncated) {
    for (int k = 0; k < static_cast<int>(mirrors.size()); ++k) {
        if (!image.chain.empty()) {
            const scene::Mirror& last = mirrors[image.chain.back()];
            if (image.chain.back() == k || !partlyInFront(last, mirrors[k]) || !partlyInFront(mirrors[k], last)) continue;
            if (image.chain.size() >= 2 && !lightCanContinue(mirrors[image.chain[image.chain.size() - 2]], last, mirrors[k]))
                continue;
        }
        MirrorImage next = image;
        next.chain.push_back(k);
        next.transform = reflection(mirrors[k]) * image.transform;
        next.weight = image.weight * mirrors[k].specular;
        if (static_cast<int>(next.chain.size()) > limits.maxDepth || luminance(next.weight) < limits.minWeight) {
            truncated = true;
            continue;
        }
        out.push_back(next);
        extend(mirrors, limits, next, out, truncated);
    }
}

}  // namespace

std::vector<MirrorImage> enumerateMirrorImages(const std::vector<scene::Mirror>& mirrors, const MirrorLimits& limits,
                                               bool* truncated) {
    std::vector<MirrorImage> out;
    bool cut = false;
    extend(mirrors, limits, MirrorImage{}, out, cut);
    if (truncated) *truncated = cut;
    return out;
}

std::vector<MirrorImage> mirrorImagesFor(const scene::Scene& scene, bool* truncated) {
    if (truncated) *truncated = false;
    if (!scene.solver.mirrorImages) return {};
    return enumerateMirrorImages(scene.mirrors, {scene.solver.mirrorDepth, scene.solver.mirrorMinWeight}, truncated);
}

MirroredGeometry mirrorGeometry(const PatchMesh& mesh, const Clustering& clustering, const MirrorImage& image) {
    MirroredGeometry g{mesh, clustering};
    for (auto& v : g.mesh.vertices) v = image.point(v);
    for (auto& p : g.mesh.patches) {
        if (image.reversesWinding()) std::swap(p.v[1], p.v[2]);
        computeGeometry(g.mesh, p);
    }
    for (auto& c : g.clustering.clusters) {
        c.centroid = image.point(c.centroid);
        c.normal = image.direction(c.normal);
        for (int a = 0; a < 3 && clustering.voxelSize > 0; ++a)
            c.voxel[a] = static_cast<int>(std::floor((c.centroid[a] - clustering.origin[a]) / clustering.voxelSize));
    }
    return g;
}

bool MirrorPath::trace(const Vec3& imagePoint, const Vec3& receiver, Vec3* leaving, const Vec3* receiverNormal) const {
    // Walk back from the receiver: the segment toward the current image must cross the
    // chain's last mirror inside its polygon; the crossing becomes the next start, and
    // the image steps back by that reflection.
    Vec3 from = receiver;
    Vec3 image = imagePoint;
    for (size_t k = m_image.chain.size(); k-- > 0;) {
        const scene::Mirror& m = m_mirrors[m_image.chain[k]];
        double a = m.side(from), b = m.side(image);
        if (!(a > 0 && b < 0)) return false;  // light arrives on the mirror's front side only
        Vec3 hit = from + (a / (a - b)) * (image - from);
        if (!scene::polygonContains(m.polygon, m.normal, hit)) return false;
        bool open = receiverNormal && from == receiver ? m_scene.visibleFromSurface(from, *receiverNormal, hit)
                                                       : m_scene.visible(from, hit);
        if (!open) return false;
        from = hit;
        image = m.reflectPoint(image);
    }
    bool open = receiverNormal && from == receiver ? m_scene.visibleFromSurface(from, *receiverNormal, image)
                                                   : m_scene.visible(from, image);
    if (!open) return false;  // the first leg, from the real source
    if (leaving) *leaving = glm::normalize(from - image);
    return true;
}

bool MirrorPath::visible(const Vec3& from, const Vec3& to) const {
    // The image end is the one behind the last mirror of the chain.
    const scene::Mirror& last = m_mirrors[m_image.chain.back()];
    if (last.side(from) < 0 && last.side(to) > 0) return trace(from, to);
    if (last.side(to) < 0 && last.side(from) > 0) return trace(to, from);
    return false;
}

bool MirrorPath::visibleFromSurface(const Vec3& x, const Vec3& n, const Vec3& to) const {
    const scene::Mirror& last = m_mirrors[m_image.chain.back()];
    if (last.side(to) < 0 && last.side(x) > 0) return trace(to, x, nullptr, &n);
    return false;
}

std::vector<std::unique_ptr<MirrorView>> mirrorViewsFor(const scene::Scene& scene, const PatchMesh& mesh,
                                                        const Clustering& clustering, const Visibility& vis,
                                                        bool* truncated) {
    std::vector<std::unique_ptr<MirrorView>> views;
    for (auto& image : mirrorImagesFor(scene, truncated)) {
        auto view = std::make_unique<MirrorView>();
        view->image = std::move(image);
        view->geometry = mirrorGeometry(mesh, clustering, view->image);
        view->path = std::make_unique<MirrorPath>(scene.mirrors, view->image, vis);
        views.push_back(std::move(view));
    }
    return views;
}

}  // namespace rayrad::radiosity
