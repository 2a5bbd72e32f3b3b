// The shooter as each source shows it (the real cluster, or its mirrored copy in an
// image) and what it sends patch→patch: the near field of a shot (see shooting_core.h).
#include <radiosity/shooting/shooting_core.h>

#include <core/ray_batch.h>
#include <radiosity/form_factors/form_factor.h>
#include <radiosity/form_factors/patch_transfer.h>

namespace rayrad::radiosity {

namespace {
/// Patch→patch: a receiver this many member-group diameters away shares one visibility
/// ray for the whole group (as the final gather does for clusters).
constexpr double kSharedRayDiameters = 2.0;
}  // namespace

template <class V>
typename ShootingCore<V>::Emission ShootingCore<V>::emission(const Shooter& from, size_t c,
                                                             const std::vector<V>& amount) const {
    Emission e{amount, {}};
    const MemberTree& tree = m_trees[c];
    if (tree.nodes.size() > 1 && m_options.shootFarDiameters > 0) {
        std::vector<Rgb> luminance(amount.size());
        for (size_t k = 0; k < amount.size(); ++k) luminance[k] = toRgb(amount[k]);
        e.far = farSources(from.mesh(), from.cluster(), tree, luminance, FarRayTargets::PowerSamples);
    }
    return e;
}

template <class V>
typename ShootingCore<V>::Delivery ShootingCore<V>::shootPatches(const Source& s, const Shooter& from, size_t c,
                                                                 const Emission& light, size_t receiver,
                                                                 std::vector<V>& into, int64_t& terms) {
    const Cluster& D = m_clustering.clusters[receiver];
    const Cluster& C = from.cluster();
    const MemberTree& tree = m_trees[c];
    const std::vector<V>& amount = light.amount;
    Delivery out;
    bool reached = false;
    for (uint32_t j : D.patches) {
        const Patch& rec = m_mesh.patches[j];
        V deltaE(0.0);
        // Every visibility ray of this receiver patch leaves from its centroid: they are
        // collected with the light each lets through and traced together.
        RayBatch<V> rays(*s.vis, rec.centroid, rec.normal, deltaE);
        // Depth first through the shooter's member tree: a node far enough sends as one
        // source with four visibility rays (stratified by its light); a leaf (a member
        // group) otherwise member by member.
        descend(tree, [&](uint32_t index, const MemberNode& node) {
            if (!light.far.empty()) {
                const FarSource& f = light.far[index];
                const double limit = m_options.shootFarDiameters * f.reach;
                if (node.size() > 1 && !f.mixed && glm::dot(f.at - rec.centroid, f.at - rec.centroid) > limit * limit) {
                    ++terms;
                    if (s.image && !s.image->mayPassToPoint(f.at, 0.5 * f.reach, rec.centroid)) return false;
                    const V e = fromRgb<V>(farField(f, rec.centroid, rec.normal, nullptr)) * s.weight;
                    // Its visibility from four rays stratified by its light, each letting a
                    // quarter through (one ray toward the brightest member hid the whole node
                    // from a receiver where an occluder hides that member alone). Samples on
                    // one member (its light is over a quarter of the node's) share one ray.
                    if (e != V(0.0))
                        for (size_t i = 0; i < f.rayTo.size();) {
                            size_t same = 1;
                            while (i + same < f.rayTo.size() && f.rayTo[i + same] == f.rayTo[i]) ++same;
                            rays.add(from.mesh().patches[C.patches[f.rayTo[i]]].centroid, (0.25 * same) * e);
                            i += same;
                        }
                    return false;
                }
            }
            if (!node.leaf()) return true;
            // A receiver farther than kSharedRayDiameters of the group's diameters sees the
            // whole group through one visibility ray, toward the member that sends it the
            // most; nearer, each member has its own.
            const Vec3 groupAt = s.image ? s.image->point(node.centroid) : node.centroid;
            if (s.image && !s.image->mayPassToPoint(groupAt, 0.5 * node.diameter, rec.centroid))
                return false;  // no light through
            const Vec3 toGroup = groupAt - rec.centroid;
            const double far = kSharedRayDiameters * node.diameter;
            const bool shared = node.size() > 1 && glm::dot(toGroup, toGroup) > far * far;
            V groupE(0.0);
            double strongest = 0;
            const Patch* strongestSource = nullptr;
            for (uint32_t m = node.begin; m < node.end; ++m) {
                const uint32_t k = tree.order[m];
                uint32_t i = C.patches[k];
                if ((i == j && !s.image) || amount[k] == V(0.0)) continue;  // a patch may see its own image
                ++terms;
                const Patch& src = from.mesh().patches[i];
                Vec3 d = src.centroid - rec.centroid;  // both must face each other
                if (glm::dot(rec.normal, d) <= 0 || glm::dot(src.normal, d) >= 0) continue;
                const double f = patchFormFactor(from.mesh(), src, rec.centroid, rec.normal, m_analyticDistance);
                if (f <= 0) continue;
                const V e = amount[k] * s.weight * (kPi * f);  // ΔE = Ks π ΔL F
                if (!shared) {
                    rays.add(src.centroid, e);
                    continue;
                }
                groupE += e;
                if (std::abs(lum(e)) > strongest) strongest = std::abs(lum(e)), strongestSource = &src;
            }
            if (shared && strongestSource)
                rays.add(strongestSource->centroid, groupE);
            else if (shared)
                deltaE += groupE;  // no member with light of its own to aim at
            return false;
        });
        rays.flush();
        into[j] += deltaE;
        out.flux += deltaE * m_patchArea[j];
        out.magnitude += std::abs(lum(deltaE)) * m_patchArea[j];
        reached |= deltaE != V(0.0);  // deliveries of both signs may cancel in the flux
    }
    if (reached) m_reached[receiver] |= kReachedPatches;
    return out;
}

template <class V>
typename ShootingCore<V>::Shooter ShootingCore<V>::shooter(const Source& s, size_t c) const {
    const Cluster& C = m_clustering.clusters[c];
    Shooter out{m_mesh, C, std::nullopt, {}};
    if (s.image) out.copy = imageCluster(m_mesh, m_clustering, c, *s.image);
    out.geometry = sourceGeometry(out.mesh(), out.cluster(), m_trees[c], m_options.shootFarDiameters);
    return out;
}

template <class V>
double ShootingCore<V>::intoMirrorBacks(const Cluster& C, const std::vector<double>& unshotPower) const {
    double flux = 0;
    for (size_t k = 0; k < C.patches.size(); ++k) {
        if (unshotPower[k] == 0) continue;
        const Patch& p = m_mesh.patches[C.patches[k]];
        for (size_t m = 0; m < m_mirrorBacks.size(); ++m) {
            const auto& back = m_mirrorBacks[m];
            double f = formFactorToPolygon(p.centroid, p.normal, back.data(), static_cast<int>(back.size()),
                                           -m_scene.mirrors[m].normal);
            flux += kPi * unshotPower[k] * f;  // Φ_i F_i→back
        }
    }
    return flux;
}

template ShootingCore<double>::Emission ShootingCore<double>::emission(const Shooter&, size_t,
                                                                       const std::vector<double>&) const;
template ShootingCore<Rgb>::Emission ShootingCore<Rgb>::emission(const Shooter&, size_t, const std::vector<Rgb>&) const;
template ShootingCore<double>::Delivery ShootingCore<double>::shootPatches(const Source&, const Shooter&, size_t,
                                                                           const Emission&, size_t,
                                                                           std::vector<double>&, int64_t&);
template ShootingCore<Rgb>::Delivery ShootingCore<Rgb>::shootPatches(const Source&, const Shooter&, size_t,
                                                                     const Emission&, size_t, std::vector<Rgb>&,
                                                                     int64_t&);
template ShootingCore<double>::Shooter ShootingCore<double>::shooter(const Source&, size_t) const;
template ShootingCore<Rgb>::Shooter ShootingCore<Rgb>::shooter(const Source&, size_t) const;
template double ShootingCore<double>::intoMirrorBacks(const Cluster&, const std::vector<double>&) const;
template double ShootingCore<Rgb>::intoMirrorBacks(const Cluster&, const std::vector<double>&) const;

}  // namespace rayrad::radiosity
