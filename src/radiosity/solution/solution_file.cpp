#include <radiosity/solution/solution_file.h>

#include <core/hash.h>

#include <core/input_error.h>
#include <scene/light_groups.h>
#include <scene/photometry.h>

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <map>
#include <type_traits>

namespace rayrad::radiosity {

namespace {

constexpr char kMagic[] = "RAYRADSOL";  // 9 bytes and a NUL
constexpr uint32_t kVersion =
    7;  // 2: light groups' parts; 3: seam profiles; 4: emitted flux; 5: unshot net flux, not ΔL per patch;
        // 6: the daylight's account (left through the openings, the sun outdoors); 7: daylight passing through
constexpr uint32_t kByteOrder = 0x01020304;

/// Appends values to a byte string; reads them back with bounds checks.
class Writer {
  public:
    template <class T>
    void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        m_out.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    template <class T>
    void putArray(const std::vector<T>& v) {
        put(static_cast<uint64_t>(v.size()));
        m_out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    void putString(const std::string& s) {
        put(static_cast<uint64_t>(s.size()));
        m_out.append(s);
    }
    std::string& bytes() { return m_out; }

  private:
    std::string m_out;
};

class Reader {
  public:
    Reader(const std::string& bytes, size_t end, const std::string& path) : m_in(bytes), m_end(end), m_path(path) {}
    template <class T>
    T get(const char* what) {
        T v;
        need(sizeof v, what);
        std::memcpy(&v, m_in.data() + m_at, sizeof v);
        m_at += sizeof v;
        return v;
    }
    /// An array of `expected` values (or none, when `orNone`).
    template <class T>
    std::vector<T> getArray(size_t expected, const char* what, bool orNone = false) {
        const auto n = get<uint64_t>(what);
        if (n != expected && !(orNone && n == 0))
            throw InputError(placeMessage(
                m_path, "", fmt::format("{}: {} values where {} were expected (a damaged file)", what, n, expected)));
        need(n * sizeof(T), what);
        std::vector<T> v(n);
        std::memcpy(v.data(), m_in.data() + m_at, n * sizeof(T));
        m_at += n * sizeof(T);
        return v;
    }
    /// An array of however many values the file says (bounded by the file's size).
    template <class T>
    std::vector<T> getAnyArray(const char* what) {
        const auto n = get<uint64_t>(what);
        if (n > (m_end - m_at) / sizeof(T)) need(m_end - m_at + 1, what);
        std::vector<T> v(n);
        std::memcpy(v.data(), m_in.data() + m_at, n * sizeof(T));
        m_at += n * sizeof(T);
        return v;
    }
    std::string getString(const char* what) {
        const auto n = get<uint64_t>(what);
        need(n, what);
        std::string out = m_in.substr(m_at, n);
        m_at += n;
        return out;
    }
    void skip(size_t n) { m_at += n; }

  private:
    void need(size_t n, const char* what) const {
        if (m_end - m_at < n)
            throw InputError(placeMessage(m_path, "", std::string("the file ends inside ") + what + " (truncated?)"));
    }
    const std::string& m_in;
    size_t m_at = 0, m_end;
    const std::string& m_path;
};

void putProfiles(Writer& w, const SeamProfiles& p) {
    w.putArray(p.seamVertices());
    w.putArray(p.edges());
}

/// Seam profiles as written by putProfiles, checked against the mesh's vertex count.
SeamProfiles getProfiles(Reader& r, size_t vertexCount, const std::string& path) {
    auto seams = r.getAnyArray<uint32_t>("the seam vertices");
    auto edges = r.getAnyArray<SeamProfiles::Edge>("the seam profiles");
    for (uint32_t v : seams)
        if (v >= vertexCount)
            throw InputError(placeMessage(path, "", "a seam vertex beyond the mesh's (a damaged file)"));
    for (const auto& e : edges)
        if (e.from >= vertexCount || e.to >= vertexCount)
            throw InputError(
                placeMessage(path, "", "a seam profile's edge beyond the mesh's vertices (a damaged file)"));
    return SeamProfiles(std::move(seams), std::move(edges));
}

uint64_t checksum(const std::string& bytes, size_t n) {
    Hash h;
    h.bytes(bytes.data(), n);
    return h.value();
}

}  // namespace

SolutionFingerprint fingerprintOf(const scene::Scene& scene, const PatchMesh& mesh) {
    SolutionFingerprint f;
    Hash g;
    g << mesh.vertices.size() << mesh.patches.size();
    for (const auto& v : mesh.vertices) g << v;
    for (const auto& p : mesh.patches) g << p.v[0] << p.v[1] << p.v[2] << p.material << p.group;
    f.geometry = g.value();

    Hash m;
    for (const auto& mat : scene.materials)
        m << mat.name << static_cast<int>(mat.kind) << Vec3(mat.reflectance) << Vec3(mat.specular) << mat.ior
          << mat.twoSided << mat.texture;
    // A texture changes the solution through the patches' mean reflectances.
    for (const auto& rho : mesh.texturedReflectance) m << Vec3(rho);
    f.materials = m.value();

    Hash l;
    for (const auto& mat : scene.materials) l << Vec3(mat.emission);  // emitters are lights
    l << scene.lights.size();
    for (const auto& light : scene.lights) {
        l << light.position << Vec3(light.intensity) << light.isSpot << light.direction << light.cosInner
          << light.cosOuter << light.nadir << light.c0 << light.photometricScale << light.photometricFlux
          << light.openingPoints.size();
        for (const auto& p : light.openingPoints) l << p;
        if (light.photometry) {
            const auto& w = *light.photometry;
            l << static_cast<int>(w.type);
            for (double a : w.vertical) l << a;
            for (double a : w.horizontal) l << a;
            for (const auto& plane : w.candela)
                for (double cd : plane) l << cd;
        }
    }
    if (const auto& d = scene.daylight) {  // the sky and the sun light the scene through its openings
        l << static_cast<int>(d->kind) << d->cieType << d->zenithLuminance << d->sunDirection
          << d->sunNormalIlluminance << d->groundReflectance << d->up << d->north;
        for (const auto& mat : scene.materials)
            if (mat.isOpening()) l << mat.transmittance;
    }
    f.lights = l.value();

    // The same with each emitter's strength over its group's (dimming a group changes no
    // ratio), and the groups' strengths.
    const auto groups = scene::lightGroups(scene);
    std::map<std::string, double> strength;
    for (const auto& name : groups) strength[name] = 0;
    auto lightStrength = [](const scene::PointLight& light) {
        return luminance(light.intensity) * light.photometricScale;
    };
    for (const auto& light : scene.lights) strength[light.lightGroup] += lightStrength(light);
    for (const auto& mat : scene.materials) strength[mat.lightGroup] += luminance(mat.emission);
    auto relative = [&](const std::string& group, double value) {
        const double total = strength[group];
        return total > 0 ? value / total : 0.0;
    };
    Hash shapes;
    shapes << scene.lights.size();
    for (const auto& light : scene.lights) {
        const double y = luminance(light.intensity);
        shapes << light.lightGroup << light.position << (y > 0 ? Vec3(light.intensity / y) : Vec3(0.0))
               << relative(light.lightGroup, lightStrength(light)) << light.isSpot << light.direction << light.cosInner
               << light.cosOuter << light.nadir << light.c0 << light.openingPoints.size();
        for (const auto& p : light.openingPoints) shapes << p;
        if (light.photometry) shapes << light.photometry->integratedFlux();
    }
    for (const auto& mat : scene.materials) {
        const double y = luminance(mat.emission);
        shapes << mat.lightGroup << (y > 0 ? Vec3(mat.emission / y) : Vec3(0.0)) << relative(mat.lightGroup, y);
    }
    f.lightShapes = shapes.value();
    for (const auto& name : groups) f.groupStrengths.emplace_back(name, strength[name]);

    // Every setting the direct pass, the shooting, the reconstruction or the seam vertices
    // read (a setting added to them must be added here). Not the sensor gather's
    // (radiosity.gather_*): the sensors are gathered after loading, with the scene's.
    Hash s;
    const auto& shoot = scene.shooting;
    const auto& rec = scene.reconstruction;
    const auto& mirrors = scene.mirrorImages;
    s << shoot.stopUnshot << shoot.maxShots << shoot.maxSeconds << scene.formFactors.analyticDistance
      << scene.direct.areaLightSamples << shoot.shootFarDiameters << rec.linear() << rec.edgeGatherLevels
      << rec.seamProfileNodes << mirrors.imageMethod() << mirrors.mirrorDepth << mirrors.mirrorMinWeight
      << mirrors.mirrorMinShare << shoot.conserveEnergy << shoot.overshoot << shoot.oneChannelWhenGrey;
    const auto& c = scene.clusters;
    s << c.enabled << c.voxelSize << c.patchesPerCluster << c.sizePercent << c.referenceArea << c.normalToleranceDeg
      << c.maxIlluminanceStep << c.energyCorrection << c.receiverDetail << c.pushPullFraction;
    f.settings = s.value();
    return f;
}

std::string encodeSolution(const RadiositySolution& sol, const SolutionFingerprint& f, size_t vertexCount,
                           const std::vector<GroupSolution>& groups) {
    Writer w;
    w.bytes().append(kMagic, sizeof kMagic);
    w.put(kVersion);
    w.put(kByteOrder);
    w.put(f.geometry), w.put(f.materials), w.put(f.lights), w.put(f.settings), w.put(f.lightShapes);
    w.put(static_cast<uint64_t>(sol.directMean.size()));
    w.put(static_cast<uint64_t>(vertexCount));
    w.putArray(sol.directMean);
    w.putArray(sol.directCorner);
    w.putArray(sol.indirect);
    w.putArray(sol.vertexIndirect);
    w.put(sol.shots), w.put(sol.emittedFlux), w.put(sol.initialUnshotFlux), w.put(sol.remainingUnshotFlux),
        w.put(sol.unshotNetFlux);
    w.put(static_cast<uint8_t>(sol.converged));
    w.put(sol.seconds), w.put(sol.mirrorAbsorbedDirect), w.put(sol.mirrorAbsorbedSecondary),
        w.put(sol.backAbsorbedDirect), w.put(sol.leftThroughOpenings), w.put(sol.outdoorDirect),
        w.put(sol.passedThrough);
    w.putArray(sol.backFlux);
    putProfiles(w, sol.seamProfiles);
    // The light groups' parts (the arrays the renderer reads), with the strengths they had.
    w.put(static_cast<uint64_t>(groups.size()));
    for (const auto& g : groups) {
        double strength = 0;
        for (const auto& [name, value] : f.groupStrengths)
            if (name == g.group) strength = value;
        w.putString(g.group);
        w.put(strength);
        w.putArray(g.solution.directMean);
        w.putArray(g.solution.directCorner);
        w.putArray(g.solution.indirect);
        w.putArray(g.solution.vertexIndirect);
        putProfiles(w, g.solution.seamProfiles);
    }
    w.put(checksum(w.bytes(), w.bytes().size()));
    return std::move(w.bytes());
}

void checkSolutionFileStart(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char head[sizeof kMagic] = {};
    in.read(head, sizeof head);
    if (!in || std::memcmp(head, kMagic, sizeof kMagic) != 0)
        throw InputError(placeMessage(path, "", "not a rayrad solution file (rayrad solve --save writes one)"));
}

RadiositySolution decodeSolution(const std::string& bytes, const std::string& path, const SolutionFingerprint& expected,
                                 size_t patchCount, size_t vertexCount) {
    auto fail = [&](const std::string& why) { return InputError(placeMessage(path, "", why)); };
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw fail("not a rayrad solution file (rayrad solve --save writes one)");
    if (bytes.size() < sizeof kMagic + 2 * sizeof(uint32_t) + sizeof(uint64_t)) throw fail("the file is truncated");
    const size_t end = bytes.size() - sizeof(uint64_t);
    Reader r(bytes, end, path);
    r.skip(sizeof kMagic);
    const auto version = r.get<uint32_t>("the version");
    if (version != kVersion)
        throw fail(
            fmt::format("a solution of format version {}; this rayrad reads version {}: solve the scene again "
                        "(rayrad solve SCENE --save FILE)",
                        version, kVersion));
    if (r.get<uint32_t>("the byte-order mark") != kByteOrder) throw fail("written on a machine of another byte order");
    uint64_t stored;
    std::memcpy(&stored, bytes.data() + end, sizeof stored);
    if (stored != checksum(bytes, end)) throw fail("its checksum does not match: the file is damaged or truncated");
    SolutionFingerprint f;
    f.geometry = r.get<uint64_t>("the fingerprint"), f.materials = r.get<uint64_t>("the fingerprint");
    f.lights = r.get<uint64_t>("the fingerprint"), f.settings = r.get<uint64_t>("the fingerprint");
    f.lightShapes = r.get<uint64_t>("the fingerprint");
    const char* differs = f.geometry != expected.geometry         ? "geometry (or its meshing settings)"
                          : f.materials != expected.materials     ? "materials"
                          : f.settings != expected.settings       ? "radiosity or cluster settings"
                          : f.lightShapes != expected.lightShapes ? "lights"
                                                                  : nullptr;
    if (differs)
        throw fail(std::string("this solution was computed for another scene: the ") + differs +
                   " differ; solve the scene again (rayrad solve SCENE --save FILE)");
    // The same lights but for the groups' dimming: only a file with the groups' parts can
    // follow it.
    const bool dimmed = f.lights != expected.lights;
    const auto patches = r.get<uint64_t>("the patch count"), vertices = r.get<uint64_t>("the vertex count");
    if (patches != patchCount || vertices != vertexCount)
        throw fail(fmt::format("{} patches and {} vertices where the scene has {} and {}", patches, vertices,
                               patchCount, vertexCount));
    RadiositySolution sol;
    sol.directMean = r.getArray<Rgb>(patchCount, "the direct illuminance");
    sol.directCorner = r.getArray<RgbF>(3 * patchCount, "the corner direct illuminance", true);
    sol.indirect = r.getArray<Rgb>(patchCount, "the indirect illuminance");
    sol.vertexIndirect = r.getArray<Rgb>(vertexCount, "the vertex values");
    sol.shots = r.get<int64_t>("the statistics");
    sol.emittedFlux = r.get<double>("the statistics");
    sol.initialUnshotFlux = r.get<double>("the statistics");
    sol.remainingUnshotFlux = r.get<double>("the statistics");
    sol.unshotNetFlux = r.get<double>("the statistics");
    sol.converged = r.get<uint8_t>("the statistics") != 0;
    sol.seconds = r.get<double>("the statistics");
    sol.mirrorAbsorbedDirect = r.get<double>("the statistics");
    sol.mirrorAbsorbedSecondary = r.get<double>("the statistics");
    sol.backAbsorbedDirect = r.get<double>("the statistics");
    sol.leftThroughOpenings = r.get<double>("the statistics");
    sol.outdoorDirect = r.get<double>("the statistics");
    sol.passedThrough = r.get<double>("the statistics");
    // One back flux per surface group, as many as were written (the checksum vouches for n).
    sol.backFlux = r.getAnyArray<double>("the back fluxes");  // bounded by the file's size
    sol.seamProfiles = getProfiles(r, vertexCount, path);
    const auto groupCount = r.get<uint64_t>("the light groups");
    if (!dimmed) return sol;  // the full solve itself (its seam profiles to be indexed by the caller)
    if (groupCount == 0 || groupCount != expected.groupStrengths.size())
        throw fail(
            "the lights differ from those the solution was computed for (only dimming whole light groups can be "
            "applied to a saved solution, and only to one saved with light groups); solve the scene again");
    // Σ_g (S'_g / S_g) part_g.
    sol.directMean.assign(patchCount, Rgb(0.0));
    sol.directCorner.assign(3 * patchCount, RgbF(0.0f));
    sol.indirect.assign(patchCount, Rgb(0.0));
    sol.vertexIndirect.assign(vertexCount, Rgb(0.0));
    sol.unshotNetFlux = 0;
    sol.seamProfiles = SeamProfiles();
    for (uint64_t g = 0; g < groupCount; ++g) {
        const std::string name = r.getString("a light group's name");
        const double then = r.get<double>("a light group's strength");
        const auto& [expectedName, now] = expected.groupStrengths[g];
        if (name != expectedName) throw fail("its light groups are not the scene's; solve the scene again");
        const double scale = then > 0 ? now / then : 0.0;
        const auto add = [&](auto& total, const auto& part) {
            if (part.size() != total.size()) return;  // corner values not kept for this part
            for (size_t i = 0; i < total.size(); ++i)
                total[i] += static_cast<std::decay_t<decltype(total[0][0])>>(scale) * part[i];
        };
        add(sol.directMean, r.getArray<Rgb>(patchCount, "a light group's direct illuminance"));
        add(sol.directCorner, r.getArray<RgbF>(3 * patchCount, "a light group's corner direct illuminance", true));
        add(sol.indirect, r.getArray<Rgb>(patchCount, "a light group's indirect illuminance"));
        add(sol.vertexIndirect, r.getArray<Rgb>(vertexCount, "a light group's vertex values"));
        sol.seamProfiles.add(getProfiles(r, vertexCount, path), scale);
    }
    return sol;
}

}  // namespace rayrad::radiosity
