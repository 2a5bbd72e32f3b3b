#include <radiosity/mirrors/mirror_images.h>

#include <radiosity/form_factors/form_factor.h>
#include <scene/polygon.h>

#include <algorithm>
#include <cmath>
#include <limits>

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
    const std::pair<Vec3, Vec3> planes[] = {
        {aImageNormal, aImage[0]}, {b.normal, b.polygon[0]}, {c.normal, c.polygon[0]}};
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
            if (image.chain.back() == k || !partlyInFront(last, mirrors[k]) || !partlyInFront(mirrors[k], last))
                continue;
            if (image.chain.size() >= 2 &&
                !lightCanContinue(mirrors[image.chain[image.chain.size() - 2]], last, mirrors[k]))
                continue;
        }
        MirrorImage next = image;
        next.chain.push_back(k);
        const glm::dmat4 r = reflection(mirrors[k]);
        next.transform = r * image.transform;
        // The new last mirror is seen directly; the earlier ones are now seen in it too.
        next.apertures = {MirrorImage::Aperture(mirrors[k].polygon, mirrors[k].normal)};
        for (const auto& a : image.apertures) {
            std::vector<Vec3> seen;
            for (const Vec3& v : a.polygon) seen.push_back(Vec3(r * glm::dvec4(v, 1.0)));
            next.apertures.emplace_back(std::move(seen), glm::normalize(Vec3(r * glm::dvec4(a.normal, 0.0))));
        }
        next.weight = image.weight * mirrors[k].specular;
        if (static_cast<int>(next.chain.size()) > limits.maxDepth || luminance(next.weight) < limits.minWeight) {
            truncated = true;
            continue;
        }
        // A ray through the chain is one straight line through every (unfolded) aperture,
        // so the étendue of any two bounds it: the new last mirror, seen back toward each
        // earlier one (whose front faces it), and the pairs the chain had already
        // (reflection keeps étendue).
        next.etendue = image.chain.empty() ? kPi * scene::polygonArea(mirrors[k].polygon) : image.etendue;
        for (size_t j = 1; j < next.apertures.size(); ++j)
            next.etendue = std::min(next.etendue, polygonEtendue(next.apertures[0].polygon, -next.apertures[0].normal,
                                                                 next.apertures[j].polygon, next.apertures[j].normal));
        const double share =
            limits.surfaceArea > 0 ? luminance(next.weight) * next.etendue / (kPi * limits.surfaceArea) : 1.0;
        if (share < limits.minShare) {
            truncated = true;
            continue;
        }
        out.push_back(next);
        extend(mirrors, limits, next, out, truncated);
    }
}

}  // namespace

MirrorImage::Aperture::Aperture(std::vector<Vec3> vertices, const Vec3& n)
    : polygon(std::move(vertices)), normal(n), centre(0.0), radius(0) {
    for (const Vec3& v : polygon) centre += v;
    centre /= static_cast<double>(polygon.size());
    for (const Vec3& v : polygon) radius = std::max(radius, glm::length(v - centre));
    if (!scene::isConvexAround(polygon, normal)) return;
    for (size_t i = 0; i < polygon.size(); ++i) {
        Vec3 out = glm::normalize(glm::cross(polygon[(i + 1) % polygon.size()] - polygon[i], normal));
        outward.push_back(glm::dot(out, centre - polygon[i]) > 0 ? -out : out);
    }
}

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
    if (!scene.mirrorImages.imageMethod()) return {};
    double area = 0;
    for (const auto& g : scene.groups)
        if (scene.materials[g.material].isDiffuse())
            for (const auto& polygon : g.polygons) area += scene::polygonArea(g.positions, polygon);
    return enumerateMirrorImages(
        scene.mirrors,
        {scene.mirrorImages.mirrorDepth, scene.mirrorImages.mirrorMinWeight, scene.mirrorImages.mirrorMinShare, area},
        truncated);
}

ImagePatch imagePatch(const PatchMesh& mesh, const Patch& p, const MirrorImage& image) {
    ImagePatch out{p, {image.point(mesh.corner(p, 0)), image.point(mesh.corner(p, 1)), image.point(mesh.corner(p, 2))}};
    if (image.reversesWinding()) std::swap(out.corners[1], out.corners[2]);
    computeGeometry(out.corners, out.patch);
    return out;
}

bool throughApertures(const std::vector<scene::Mirror>& mirrors, const MirrorImage& image, const Vec3& imagePoint,
                      const Vec3& receiver, std::vector<Vec3>* hits) {
    // Walk back from the receiver: the segment toward the current image must cross the
    // chain's last mirror inside its polygon; the crossing becomes the next start, and
    // the image steps back by that reflection.
    if (hits) hits->clear();
    Vec3 from = receiver, to = imagePoint;
    for (size_t k = image.chain.size(); k-- > 0;) {
        const scene::Mirror& m = mirrors[image.chain[k]];
        double a = m.side(from), b = m.side(to);
        // Light arrives on the mirror's front side only, and never at a point in the
        // mirror's own plane (within rounding of it: a point on the mirror itself, or
        // on a surface flush with it, would otherwise see its own reflection at distance 0).
        const double rounding = 1e-12 * std::max(glm::length(from), glm::length(to - from));
        if (!(a > rounding && b < -rounding)) return false;
        Vec3 hit = from + (a / (a - b)) * (to - from);
        if (!scene::polygonContains(m.polygon, m.normal, hit)) return false;
        if (hits) hits->push_back(hit);
        from = hit;
        to = m.reflectPoint(to);
    }
    if (hits) hits->push_back(to);  // the real source
    return true;
}

namespace {

/// Sutherland–Hodgman: the part of polygon `poly` where m·(p − a) ≥ 0.
std::vector<Vec3> clipToHalfSpace(const std::vector<Vec3>& poly, const Vec3& m, const Vec3& a) {
    std::vector<Vec3> out;
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3 &p = poly[i], &q = poly[(i + 1) % n];
        const double dp = glm::dot(m, p - a), dq = glm::dot(m, q - a);
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
    }
    return out;
}

}  // namespace

std::vector<Vec3> clipToApertures(const MirrorImage& image, std::vector<Vec3> source, const Vec3& x) {
    for (const MirrorImage::Aperture& a : image.apertures) {
        if (source.size() < 3) break;
        const Vec3& centre = a.centre;
        // Behind the (unfolded) mirror, seen from x.
        if (glm::dot(a.normal, x - centre) <= 0) return {};
        source = clipToHalfSpace(source, -a.normal, centre);
        // Inside the cone from x through the aperture: on the aperture's side of the
        // plane through x and each edge.
        for (size_t e = 0; e < a.polygon.size() && source.size() >= 3; ++e) {
            const Vec3 &p = a.polygon[e], &q = a.polygon[(e + 1) % a.polygon.size()];
            Vec3 plane = glm::cross(q - p, x - p);
            if (glm::dot(plane, centre - p) < 0) plane = -plane;
            source = clipToHalfSpace(source, plane, p);
        }
    }
    if (source.size() < 3) return {};
    return source;
}

bool MirrorImage::mayPass(const Vec3& imageCentre, double imageRadius, const Vec3& receiver,
                          double receiverRadius) const {
    const double reach = std::max(imageRadius, receiverRadius) + 1e-9;  // m, with rounding's margin
    // First against each aperture's bounding ball (a few flops), then exactly.
    const Vec3 d = receiver - imageCentre;
    const double length2 = glm::dot(d, d);
    for (const Aperture& a : apertures) {
        const double t = length2 > 0 ? std::clamp(glm::dot(a.centre - imageCentre, d) / length2, 0.0, 1.0) : 0.0;
        const Vec3 off = imageCentre + t * d - a.centre;
        const double limit = reach + a.radius;
        if (glm::dot(off, off) > limit * limit) return false;
    }
    for (const Aperture& a : apertures) {
        // A segment that crosses a convex aperture's plane at X, a distance D outside its
        // outline, passes no nearer to it than D sinθ (θ the segment's angle with the
        // plane; the outline lies inside each edge's line, so D ≥ the largest distance of
        // X outside an edge's line). That bound decides (a pass it lets through is
        // conservative: the rays decide); other segments take the exact distance.
        const double da = glm::dot(a.normal, imageCentre - a.centre), db = glm::dot(a.normal, receiver - a.centre);
        if (!a.outward.empty() && (da < 0) != (db < 0)) {
            const Vec3 crossing = imageCentre + (da / (da - db)) * d;
            double outside = -std::numeric_limits<double>::infinity();
            for (size_t i = 0; i < a.outward.size(); ++i)
                outside = std::max(outside, glm::dot(a.outward[i], crossing - a.polygon[i]));
            if (outside * std::abs(da - db) > reach * std::sqrt(length2)) return false;
            continue;
        }
        if (scene::segmentPolygonDistance(imageCentre, receiver, a.polygon, a.normal) > reach) return false;
    }
    return true;
}

bool MirrorImage::mayPassToPoint(const Vec3& imageCentre, double imageRadius, const Vec3& receiver) const {
    constexpr double kMargin = 1e-9;  // m, rounding's margin
    const Vec3 axis = imageCentre - receiver;
    const double length = glm::length(axis);
    if (length <= imageRadius + kMargin) return true;  // x inside the ball
    const Vec3 unit = axis / length;
    const double sinA = imageRadius / length, cosA = std::sqrt(1 - sinA * sinA);
    for (const Aperture& a : apertures) {
        // Against the aperture's bounding ball first: a point of the cone at a distance u
        // along the axis is within min(u tan α, R) of it.
        const Vec3 w = a.centre - receiver;
        const double u = glm::dot(w, unit);
        if (u + a.radius < 0 || u - a.radius > length + imageRadius) return false;
        const double off = std::sqrt(std::max(0.0, glm::dot(w, w) - u * u));  // from the axis
        const double spread = std::min((u + a.radius) * sinA / cosA, imageRadius);
        if (off > a.radius + spread + kMargin) return false;
    }
    for (const Aperture& a : apertures) {
        const double dx = glm::dot(a.normal, receiver - a.centre), dc = glm::dot(a.normal, imageCentre - a.centre);
        if ((dx < 0) == (dc < 0) && std::abs(dc) > imageRadius + kMargin) return false;  // the ball on x's side
        if (a.outward.empty() || (dx < 0) == (dc < 0)) continue;                         // the rays decide
        const double sinT = std::abs(dx - dc) / length;  // the axis's angle θ with the plane
        const double sinTA = sinT * cosA - std::sqrt(std::max(0.0, 1 - sinT * sinT)) * sinA;  // sin(θ − α)
        if (!(sinTA > 0)) continue;                // the cone grazes the plane: its section is unbounded
        const double s = length * dx / (dx - dc);  // m, from x to the crossing
        const Vec3 crossing = receiver + s * unit;
        double outside = -std::numeric_limits<double>::infinity();  // ≤ the crossing's distance to the outline
        for (size_t i = 0; i < a.outward.size(); ++i)
            outside = std::max(outside, glm::dot(a.outward[i], crossing - a.polygon[i]));
        if (outside > s * sinA / sinTA + kMargin) return false;
    }
    return true;
}

bool MirrorPath::trace(const Vec3& imagePoint, const Vec3& receiver, Vec3* leaving, const Vec3* receiverNormal) const {
    thread_local std::vector<Vec3> hits;
    if (!throughApertures(m_mirrors, m_image, imagePoint, receiver, &hits)) return false;
    // Every real leg must be unoccluded: receiver → first hit → … → the real source.
    Vec3 from = receiver;
    for (const Vec3& to : hits) {
        bool open = receiverNormal && from == receiver ? m_scene.visibleFromSurface(from, *receiverNormal, to)
                                                       : m_scene.visible(from, to);
        if (!open) return false;
        from = to;
    }
    if (leaving) *leaving = glm::normalize(hits[hits.size() - 2] - hits.back());  // from the source to the first mirror
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

std::vector<std::unique_ptr<MirrorView>> mirrorViewsFor(const scene::Scene& scene, const Visibility& vis,
                                                        bool* truncated) {
    std::vector<std::unique_ptr<MirrorView>> views;
    for (auto& image : mirrorImagesFor(scene, truncated)) {
        auto view = std::make_unique<MirrorView>();
        view->image = std::move(image);
        view->path = std::make_unique<MirrorPath>(scene.mirrors, view->image, vis);
        views.push_back(std::move(view));
    }
    return views;
}

}  // namespace rayrad::radiosity
