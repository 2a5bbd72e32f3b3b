// SceneDesc (plain data) → Scene (world space, materials resolved, meshes loaded).
#include <scene/scene.h>

#include <core/input_error.h>
#include <core/input_file.h>
#include <scene/camera_path.h>
#include <scene/json_reader.h>
#include <scene/mesh_import.h>
#include <scene/polygon.h>
#include <scene/sensor_names.h>
#include <scene/surface_grids.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

namespace rayrad::scene {

/// A file's flat polished metal of more triangles than this stays diffuse: each triangle
/// would be a mirror of the image method, with its own virtual lights.
constexpr size_t kMaxFileMirrorTriangles = 8;

Rgb PointLight::intensityToward(const Vec3& w) const {
    if (photometry) {
        // The luminaire's frame: C0, C90 = (−nadir) × C0, nadir.
        const Vec3 c90 = glm::cross(-nadir, c0);
        return intensity *
               (photometricScale * photometry->intensityToward(glm::dot(w, c0), glm::dot(w, c90), glm::dot(w, nadir)));
    }
    if (!isSpot) return intensity;
    double c = glm::dot(w, direction);
    if (c >= cosInner) return intensity;
    if (c <= cosOuter) return Rgb(0.0);
    double t = (c - cosOuter) / (cosInner - cosOuter);
    return intensity * (t * t * (3 - 2 * t));  // smoothstep between the cones
}

size_t Scene::polygonCount() const {
    size_t n = 0;
    for (const auto& g : groups) n += g.polygons.size();
    return n;
}

bool Scene::hasReflectance() const {
    for (const auto& g : groups)
        if (glm::length(materials[g.material].reflectance) > 0) return true;
    return false;
}

namespace {

Vec3 transformPoint(const glm::dmat4& m, const Vec3& p) {
    return Vec3(m * glm::dvec4(p, 1.0));
}

/// A box's six faces, each a quad CCW seen from outside.
std::vector<std::vector<Vec3>> boxFaces(const Vec3& lo, const Vec3& hi) {
    auto P = [&](int x, int y, int z) { return Vec3(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z); };
    return {
        {P(0, 0, 0), P(0, 0, 1), P(0, 1, 1), P(0, 1, 0)},  // -x
        {P(1, 0, 0), P(1, 1, 0), P(1, 1, 1), P(1, 0, 1)},  // +x
        {P(0, 0, 0), P(1, 0, 0), P(1, 0, 1), P(0, 0, 1)},  // -y
        {P(0, 1, 0), P(0, 1, 1), P(1, 1, 1), P(1, 1, 0)},  // +y
        {P(0, 0, 0), P(0, 1, 0), P(1, 1, 0), P(1, 0, 0)},  // -z
        {P(0, 0, 1), P(1, 0, 1), P(1, 1, 1), P(0, 1, 1)},  // +z
    };
}

/// A sphere as a projected cube: each face an n×n grid of cells, two triangles each,
/// so 12·n² triangles. Equal-angle mapping keeps the triangles close in size.
SurfaceGroup cubeSphere(const Vec3& center, double radius, int n) {
    SurfaceGroup g;
    std::map<std::tuple<int, int, int>, uint32_t> index;  // integer lattice point on the cube → vertex
    auto vertex = [&](int i, int j, int k) {
        auto key = std::make_tuple(i, j, k);
        auto it = index.find(key);
        if (it != index.end()) return it->second;
        auto angle = [n](int a) { return std::tan((2.0 * a / n - 1.0) * kPi / 4.0); };
        Vec3 d = glm::normalize(Vec3(angle(i), angle(j), angle(k)));
        auto id = static_cast<uint32_t>(g.positions.size());
        g.positions.push_back(center + radius * d);
        index.emplace(key, id);
        return id;
    };
    // For each axis and side: lattice coordinates (u, v) on the face, outward CCW order.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            int ua = (axis + 1) % 3, va = (axis + 2) % 3;
            auto at = [&](int u, int v) {
                int c[3];
                c[axis] = side ? n : 0;
                c[ua] = u;
                c[va] = v;
                return vertex(c[0], c[1], c[2]);
            };
            for (int u = 0; u < n; ++u)
                for (int v = 0; v < n; ++v) {
                    uint32_t a = at(u, v), b = at(u + 1, v), c = at(u + 1, v + 1), d = at(u, v + 1);
                    // (ua × va) = +axis: CCW seen from +axis; flip for the negative side.
                    bool flip = side == 0;
                    bool diag = ((u + v) & 1) != 0;  // alternate diagonals for symmetry
                    std::vector<std::vector<uint32_t>> tris =
                        diag ? std::vector<std::vector<uint32_t>>{{a, b, c}, {a, c, d}}
                             : std::vector<std::vector<uint32_t>>{{a, b, d}, {b, c, d}};
                    for (auto& t : tris) {
                        if (flip) std::swap(t[1], t[2]);
                        g.polygons.push_back(t);
                    }
                }
        }
    return g;
}

class Builder {
  public:
    explicit Builder(const SceneDesc& desc) : m_desc(desc) {}

    Scene build() {
        Scene s;
        s.file = m_desc.file;
        static_cast<Settings&>(s) = m_desc;
        std::map<std::string, int> materialIndex;
        for (const auto& m : m_desc.materials) {
            materialIndex[m.name] = static_cast<int>(s.materials.size());
            Material mat;
            mat.name = m.name;
            mat.kind = m.kind;
            mat.reflectance = m.reflectance;
            mat.specular = m.specular;
            mat.ior = m.ior;
            mat.transmittance = m.transmittance;
            mat.twoSided = m.twoSided;
            mat.lightGroup = m.lightGroup;
            if (m.emissive && m.luminance > 0) mat.emission = m.color / luminance(m.color) * m.luminance;
            if (!m.texture.empty()) mat.texture = textureIndex(s, m.resolvedTexture, m.where + "/texture");
            s.materials.push_back(mat);
        }
        for (const auto& o : m_desc.objects) addObject(s, o, o.material.empty() ? -1 : materialIndex.at(o.material));
        addBackSides(s);
        collectMirrors(s);
        resolveFluxes(s);
        for (const auto& l : m_desc.lights) s.lights.push_back(makeLight(l));
        for (const auto& l : m_fileLights) s.lights.push_back(l);
        s.daylight = m_desc.daylight;
        bool anyEmitter = !s.lights.empty() || s.daylight.has_value();
        for (const auto& g : s.groups) anyEmitter |= s.materials[g.material].isEmissive();
        if (!anyEmitter)
            fail("/lights", "the scene has no light: add a light or an emissive material (the mesh files bring none)");
        s.sensors.reserve(m_desc.sensors.size());
        for (const auto& d : m_desc.sensors)
            s.sensors.push_back(
                {d.name, d.grid, d.gridU, d.gridV, d.position, d.normal, d.refDirect, d.refIndirect, d.refTotal});
        addSurfaceGrids(s);
        s.observers = m_desc.observers;
        if (m_desc.camera) s.camera = camera(s, *m_desc.camera);
        for (const auto& [name, c] : m_desc.views) s.views.push_back({name, camera(s, c)});
        if (m_desc.cameraPath) s.pathFrames = pathFrames(s, *m_desc.cameraPath);
        computeBounds(s);
        return s;
    }

  private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw InputError(placeMessage(m_desc.file, where, what));
    }

    /// The image file's index in s.textures, added once; the file must be readable.
    int textureIndex(Scene& s, const std::string& file, const std::string& where) {
        const auto it = std::find(s.textures.begin(), s.textures.end(), file);
        if (it != s.textures.end()) return static_cast<int>(it - s.textures.begin());
        if (const std::string problem = inputFileProblem(file, "texture image"); !problem.empty())
            fail(where, file + ": " + problem);
        s.textures.push_back(file);
        return static_cast<int>(s.textures.size()) - 1;
    }

    /// A textured quad's corner coordinates: corner 0 at the image's bottom left, 1 bottom
    /// right, 3 top left, the image repeating `repeat` times; reversed with the corners.
    std::vector<glm::dvec2> quadUvs(int material, bool reversed) const {
        const glm::dvec2 r = m_desc.materials[static_cast<size_t>(material)].textureRepeat;
        std::vector<glm::dvec2> uvs = {{0, 0}, {r.x, 0}, {r.x, r.y}, {0, r.y}};
        if (reversed) std::reverse(uvs.begin(), uvs.end());
        return uvs;
    }

    bool textured(const Scene& s, int material) const { return material >= 0 && s.materials[material].texture >= 0; }

    void addPolygonGroup(Scene& s, std::vector<Vec3> v, int material, const std::string& where, bool isQuad,
                         std::vector<glm::dvec2> uvs = {}) {
        double area = polygonArea(v);
        double size = 0;
        for (const auto& p : v) size = std::max(size, glm::length(p - v[0]));
        if (!(area > 1e-12 * size * size) || size == 0) fail(where + "/vertices", "the polygon has zero area");
        Vec3 n = polygonNormal(v);
        if (!isQuad) {
            double off = maxPlaneDistance(v);
            if (off > 1e-4 * size)
                fail(where + "/vertices",
                     fmt::format("the polygon is not planar (a vertex is {:.3g} m off its plane)", off));
        }
        if (!isConvexAround(v, n) && isQuad)
            fail(where + "/vertices", "the quad is not convex (check the vertex order)");
        SurfaceGroup g;
        g.positions = std::move(v);
        g.polygons.push_back({});
        for (uint32_t i = 0; i < g.positions.size(); ++i) g.polygons[0].push_back(i);
        if (!uvs.empty()) g.polygonUvs.push_back(std::move(uvs));
        g.material = material;
        g.where = where;
        s.groups.push_back(std::move(g));
    }

    void addObject(Scene& s, const ObjectDesc& o, int material) {
        const glm::dmat4& m = o.transform;
        bool mirrored = glm::determinant(glm::dmat3(m)) < 0;
        auto place = [&](std::vector<Vec3> v, bool reverse) {
            for (auto& p : v) p = transformPoint(m, p);
            if (reverse != mirrored) std::reverse(v.begin(), v.end());
            return v;
        };
        if (material >= 0 && s.materials[material].kind == SurfaceKind::Mirror &&
            (o.kind == ObjectKind::Sphere || o.kind == ObjectKind::Mesh))
            fail(o.where + "/material",
                 "a mirror must be a quad, polygon or box (the image method needs a few planes, "
                 "not a curved surface)");
        if (textured(s, material) && (o.kind == ObjectKind::Polygon || o.kind == ObjectKind::Sphere))
            fail(o.where + "/material",
                 "a texture is mapped onto quads, boxes and meshes with texture coordinates, "
                 "not onto a polygon or a sphere");
        switch (o.kind) {
            case ObjectKind::Quad:
            case ObjectKind::Polygon:
                addPolygonGroup(s, place(o.vertices, false), material, o.where, o.kind == ObjectKind::Quad,
                                textured(s, material) ? quadUvs(material, mirrored) : std::vector<glm::dvec2>{});
                break;
            case ObjectKind::Box:
                for (auto& face : boxFaces(o.boxMin, o.boxMax))
                    addPolygonGroup(
                        s, place(face, o.inward), material, o.where, true,
                        textured(s, material) ? quadUvs(material, o.inward != mirrored) : std::vector<glm::dvec2>{});
                break;
            case ObjectKind::Sphere: {
                SurfaceGroup g = cubeSphere(o.center, o.radius, o.subdivisions);
                if (finishMeshGroup(s, std::move(g), m, o.inward != mirrored, material, o.where, o.keepAbove) == 0)
                    failEmpty(o.where, o.keepAbove);
                break;
            }
            case ObjectKind::Mesh:
                addMesh(s, o, material, mirrored);
                break;
        }
    }

    /// A mesh file: one surface group per material. `material` ≥ 0 (the object's JSON
    /// material) overrides the file's materials; −1 takes them from the file (OBJ .mtl,
    /// glTF), each becoming a scene material named "<file>:<name>". The file's punctual
    /// lights (glTF KHR_lights_punctual) join the scene's lights.
    void addMesh(Scene& s, const ObjectDesc& o, int material, bool mirrored) {
        ImportedMesh mesh = importMesh(o.resolvedFile, m_desc.file, o.where);
        if (mesh.droppedFaces > 0) s.warnings.droppedMeshFaces += static_cast<int>(mesh.droppedFaces);
        for (const auto& w : mesh.warnings) s.warnings.fileWarnings.push_back(o.where + "/file: " + w);
        if (material < 0)
            for (const auto& w : mesh.materialWarnings) s.warnings.fileWarnings.push_back(o.where + "/file: " + w);
        if (o.fileUnit == 0) checkUnit(s, o, mesh);
        std::map<int, SurfaceGroup> byMaterial;           // scene material → its triangles
        std::map<int, const ImportedMaterial*> fromFile;  // scene material → the file's
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            int m = material;
            if (m < 0) {
                int fileIndex = mesh.triangleMaterial[t];
                if (fileIndex < 0)
                    fail(o.where + "/material",
                         "the mesh file gives some triangles no material: give the object a "
                         "\"material\"");
                m = fileMaterial(s, o, mesh.materials[fileIndex]);
                fromFile[m] = &mesh.materials[fileIndex];
            }
            SurfaceGroup& g = byMaterial[m];
            g.polygons.push_back(mesh.triangles[t]);
            if (textured(s, m)) {
                if (t >= mesh.triangleUvs.size())
                    fail(o.where + "/file", "material \"" + s.materials[m].name +
                                                "\" has a texture, but the mesh gives its "
                                                "triangles no texture coordinates");
                g.polygonUvs.emplace_back(mesh.triangleUvs[t].begin(), mesh.triangleUvs[t].end());
            }
        }
        mirrorPolishedMetal(s, o, mesh.positions, fromFile, byMaterial);
        size_t kept = 0;
        for (auto& [m, g] : byMaterial) {
            g.positions = mesh.positions;
            kept += finishMeshGroup(s, std::move(g), o.transform, mirrored, m, o.where, o.keepAbove);
        }
        if (kept == 0) failEmpty(o.where, o.keepAbove);
        for (const auto& l : mesh.lights) {
            PointLight p;
            p.where = o.where + "/file (light \"" + l.name + "\")";
            p.position = transformPoint(o.transform, l.position);
            p.intensity = l.intensity;
            if (l.isSpot) {
                p.isSpot = true;
                p.direction = glm::normalize(glm::dmat3(o.transform) * l.direction);
                p.cosInner = std::cos(glm::radians(std::min(l.innerAngleDeg, l.outerAngleDeg)));
                p.cosOuter = std::cos(glm::radians(l.outerAngleDeg));
                if (p.cosInner - p.cosOuter < 1e-12) p.cosInner = p.cosOuter + 1e-12;
            }
            if (luminance(p.intensity) > 0) m_fileLights.push_back(p);
        }
    }

    /// A mesh as large as a building site in millimetres: a room modelled in mm and read as
    /// metres is 1 000 times too large, and its lamps' light reads 10⁶ times too dark.
    static void checkUnit(Scene& s, const ObjectDesc& o, const ImportedMesh& mesh) {
        Vec3 lo(1e300), hi(-1e300);
        for (const auto& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const Vec3 size = hi - lo;
        const double largest = std::max({size.x, size.y, size.z});
        if (!(largest > 1000)) return;
        s.warnings.fileWarnings.push_back(
            fmt::format("{}/file: the mesh spans {:.4g} × {:.4g} × {:.4g} units, read as metres; if it is modelled in "
                        "millimetres ({:.3g} × {:.3g} × {:.3g} m), give the object \"units\": \"mm\" — read as "
                        "metres, its lamps' light reads a million times too dark",
                        o.where, size.x, size.y, size.z, size.x / 1000, size.y / 1000, size.z / 1000));
    }

    /// The scene material for a file's material, created once per file and name; a JSON
    /// material of that name ("FILE:NAME", as info lists them) takes its place.
    /// A file's polished metal (ImportedMaterial::mirrorLike) becomes a mirror where its
    /// triangles in this mesh are few (kMaxFileMirrorTriangles: each is a mirror of the image
    /// method) and lie in one plane; elsewhere it stays diffuse with its base colour. Either
    /// way a warning says which.
    void mirrorPolishedMetal(Scene& s, const ObjectDesc& o, const std::vector<Vec3>& positions,
                             const std::map<int, const ImportedMaterial*>& fromFile,
                             std::map<int, SurfaceGroup>& byMaterial) {
        for (const auto& [m, file] : fromFile) {
            if (!file->mirrorLike || s.materials[static_cast<size_t>(m)].kind != SurfaceKind::Diffuse) continue;
            SurfaceGroup& g = byMaterial[m];
            if (g.polygons.size() > kMaxFileMirrorTriangles || !trianglesInOnePlane(positions, g.polygons)) {
                s.warnings.fileWarnings.push_back(fmt::format(
                    "{}/file: material \"{}\" is polished metal, but its {} triangles {}: read as diffuse with its "
                    "base colour",
                    o.where, file->name, g.polygons.size(),
                    g.polygons.size() > kMaxFileMirrorTriangles ? "are too many for mirrors"
                                                                : "do not lie in one plane"));
                continue;
            }
            const int mirror = fileMirrorMaterial(s, o, *file);
            s.warnings.fileWarnings.push_back(fmt::format(
                "{}/file: material \"{}\" is polished metal on a plane: read as a mirror (Ks = its base colour)",
                o.where, file->name));
            SurfaceGroup moved = std::move(g);
            byMaterial.erase(m);
            byMaterial[mirror] = std::move(moved);
        }
    }

    /// The mirror material "<file>:<name> (mirror)", specular reflectance the base colour.
    int fileMirrorMaterial(Scene& s, const ObjectDesc& o, const ImportedMaterial& m) {
        const std::string name = o.file + ":" + m.name + " (mirror)";
        if (auto it = m_fileMaterials.find(name); it != m_fileMaterials.end()) return it->second;
        Material mat;
        mat.name = name;
        mat.kind = SurfaceKind::Mirror;
        for (int c = 0; c < 3; ++c) mat.specular[c] = std::clamp(m.hasReflectance ? m.reflectance[c] : 1.0, 0.0, 1.0);
        const int index = static_cast<int>(s.materials.size());
        s.materials.push_back(mat);
        m_fileMaterials.emplace(name, index);
        return index;
    }

    int fileMaterial(Scene& s, const ObjectDesc& o, const ImportedMaterial& m) {
        std::string name = o.file + ":" + m.name;
        auto it = m_fileMaterials.find(name);
        if (it != m_fileMaterials.end()) return it->second;
        for (size_t i = 0; i < m_desc.materials.size() && i < s.materials.size(); ++i)
            if (s.materials[i].name == name) {
                m_fileMaterials.emplace(name, static_cast<int>(i));
                return static_cast<int>(i);
            }
        Material mat;
        mat.name = name;
        mat.kind = SurfaceKind::Diffuse;
        mat.emission = m.emission;
        if (m.glass) {  // clear glass: no colour, no texture
            mat.kind = SurfaceKind::Glass;
            mat.ior = m.ior;
            const int index = static_cast<int>(s.materials.size());
            s.materials.push_back(mat);
            m_fileMaterials.emplace(name, index);
            return index;
        }
        mat.twoSided = m.twoSided && m.emission == Rgb(0.0);
        std::string textureFile;
        if (!m.diffuseTexture.empty()) {
            const std::filesystem::path t(m.diffuseTexture);
            textureFile =
                t.is_absolute() ? t.string() : (std::filesystem::path(o.resolvedFile).parent_path() / t).string();
            // Models often arrive without their images: a missing one is a warning, and the
            // material keeps its plain colour.
            if (const std::string problem = inputFileProblem(textureFile, "texture image"); !problem.empty()) {
                s.warnings.fileWarnings.push_back(
                    fmt::format("{}/file: material \"{}\": texture {}: {} (its colour is used)", o.where, m.name,
                                textureFile, problem));
                textureFile.clear();
            }
        }
        if (!textureFile.empty()) {
            // The file's colour multiplies the texture (OBJ Kd × map_Kd, glTF baseColorFactor
            // × baseColorTexture); the product is clamped where it is looked up.
            mat.texture = textureIndex(s, textureFile, o.where + "/file (material \"" + m.name + "\")");
            for (int c = 0; c < 3; ++c)
                mat.reflectance[c] = m.hasReflectance ? std::clamp(m.reflectance[c], 0.0, 1.0) : 1.0;
        } else {
            // Reflectance must stay below 1 for the radiosity to converge; files often say 1.
            for (int c = 0; c < 3; ++c) mat.reflectance[c] = std::clamp(m.reflectance[c], 0.0, kMaxFileReflectance);
            if (m.reflectance.r > kMaxFileReflectance || m.reflectance.g > kMaxFileReflectance ||
                m.reflectance.b > kMaxFileReflectance)
                ++s.warnings.clampedFileReflectances;
        }
        int index = static_cast<int>(s.materials.size());
        s.materials.push_back(mat);
        m_fileMaterials.emplace(name, index);
        return index;
    }

    /// Transforms a triangle mesh, keeps the triangles above the clipping planes, drops
    /// zero-area and duplicate triangles (counted) and vertices no triangle uses.
    /// Returns the triangles kept; with none, nothing is added (the caller says whether that
    /// is an error: a mesh of several materials may have one wholly below "keep_above").
    size_t finishMeshGroup(Scene& s, SurfaceGroup g, const glm::dmat4& m, bool reverse, int material,
                           const std::string& where, const std::vector<std::pair<Vec3, double>>& keepAbove) {
        for (auto& p : g.positions) p = transformPoint(m, p);
        checkWithinRange(g, where);  // before the areas: a triangle 1e30 m long is not a sliver
        double size = 0;
        for (const auto& p : g.positions) size = std::max(size, glm::length(p - g.positions[0]));
        auto above = [&](const std::vector<uint32_t>& t) {
            for (const auto& [n, offset] : keepAbove)
                for (uint32_t i : t)
                    if (glm::dot(n, g.positions[i]) - offset < -1e-9 * size) return false;
            return true;
        };
        std::vector<std::vector<uint32_t>> kept;
        std::vector<std::vector<glm::dvec2>> keptUvs;
        std::map<std::array<uint32_t, 3>, int> seen;
        for (size_t k = 0; k < g.polygons.size(); ++k) {
            auto t = g.polygons[k];
            if (!above(t)) continue;
            std::vector<glm::dvec2> uvs = g.polygonUvs.empty() ? std::vector<glm::dvec2>{} : g.polygonUvs[k];
            if (reverse) std::reverse(t.begin(), t.end()), std::reverse(uvs.begin(), uvs.end());
            const Vec3 &a = g.positions[t[0]], &b = g.positions[t[1]], &c = g.positions[t[2]];
            double scale = std::max({glm::length(b - a), glm::length(c - a), glm::length(c - b)});
            double area2 = glm::length(glm::cross(b - a, c - a));
            std::array<uint32_t, 3> key{t[0], t[1], t[2]};
            std::sort(key.begin(), key.end());
            if (!(area2 > 1e-12 * scale * scale) || seen[key]++ > 0) {
                ++s.warnings.degeneratePolygons;
                continue;
            }
            kept.push_back(t);
            if (!uvs.empty()) keptUvs.push_back(std::move(uvs));
        }
        if (kept.empty()) return 0;
        // Renumber the vertices the kept triangles use.
        std::vector<int64_t> renumber(g.positions.size(), -1);
        std::vector<Vec3> used;
        for (auto& t : kept)
            for (auto& i : t) {
                if (renumber[i] < 0) renumber[i] = static_cast<int64_t>(used.size()), used.push_back(g.positions[i]);
                i = static_cast<uint32_t>(renumber[i]);
            }
        g.positions = std::move(used);
        g.polygons = std::move(kept);
        g.polygonUvs = std::move(keptUvs);
        g.material = material;
        g.where = where;
        const size_t count = g.polygons.size();
        s.groups.push_back(std::move(g));
        return count;
    }

    [[noreturn]] void failEmpty(const std::string& where, const std::vector<std::pair<Vec3, double>>& keepAbove) const {
        fail(where, keepAbove.empty() ? "every triangle of the mesh has zero area"
                                      : "no triangle of the mesh is above the \"keep_above\" planes");
    }

    /// Two-sided diffuse surfaces: the back is a coincident surface wound the other way,
    /// with the back reflectance (a material "<name> (back)"). To the radiosity they are
    /// two back-to-back surfaces, which never exchange light through each other.
    void addBackSides(Scene& s) const {
        std::map<int, int> backOf;  // front material → back material
        const size_t groups = s.groups.size();
        for (size_t gi = 0; gi < groups; ++gi) {
            const int m = s.groups[gi].material;
            if (!s.materials[m].twoSided) continue;
            if (!backOf.count(m)) {
                Material back = s.materials[m];
                back.name += " (back)";
                // A scene material may give its back another reflectance; a file's has the front's.
                if (static_cast<size_t>(m) < m_desc.materials.size() &&
                    m_desc.materials[static_cast<size_t>(m)].backReflectance)
                    back.reflectance = *m_desc.materials[static_cast<size_t>(m)].backReflectance;
                backOf[m] = static_cast<int>(s.materials.size());
                s.materials.push_back(back);
            }
            SurfaceGroup back = s.groups[gi];
            for (auto& poly : back.polygons) std::reverse(poly.begin(), poly.end());
            for (auto& uvs : back.polygonUvs) std::reverse(uvs.begin(), uvs.end());
            back.material = backOf[m];
            back.where += " (back side)";
            s.groups.push_back(std::move(back));
        }
    }

    /// Every polygon of every mirror surface becomes a Mirror (its plane and outline).
    static void collectMirrors(Scene& s) {
        for (const auto& g : s.groups) {
            const Material& mat = s.materials[g.material];
            if (mat.kind != SurfaceKind::Mirror) continue;
            for (const auto& poly : g.polygons) {
                Mirror m;
                for (uint32_t i : poly) m.polygon.push_back(g.positions[i]);
                m.normal = polygonNormal(m.polygon);
                m.offset = glm::dot(m.normal, m.polygon[0]);
                m.specular = mat.specular;
                m.where = g.where;
                s.mirrors.push_back(std::move(m));
            }
        }
    }

    /// flux_lm → luminance: a one-sided Lambertian emitter of area A and luminance L
    /// emits Φ = π L A.
    void resolveFluxes(Scene& s) {
        for (size_t mi = 0; mi < m_desc.materials.size(); ++mi) {
            const auto& md = m_desc.materials[mi];
            if (!md.emissive || md.flux <= 0) continue;
            double area = 0;
            for (const auto& g : s.groups)
                if (g.material == static_cast<int>(mi))
                    for (const auto& poly : g.polygons) area += polygonArea(g.positions, poly);
            if (area <= 0)
                fail(md.where + "/flux_lm", "no surface uses this emissive material, so its flux has no area");
            s.materials[mi].emission = md.color / luminance(md.color) * (md.flux / (kPi * area));
        }
    }

    PointLight makeLight(const LightDesc& l) {
        PointLight p;
        p.where = l.where;
        p.lightGroup = l.lightGroup;
        p.position = l.position;
        p.intensity = l.color * l.intensity;
        if (l.kind == LightKind::Luminaire) {
            auto& web = m_photometry[l.resolvedFile];
            if (!web) {
                try {
                    web = std::make_shared<const Photometry>(readPhotometry(l.resolvedFile));
                } catch (const InputError& e) {
                    fail(l.where + "/file", e.what());
                }
            }
            const double fileFlux = web->integratedFlux();
            if (!(fileFlux > 0))
                fail(l.where + "/file", "'" + l.resolvedFile + "' emits no light (its candela table is zero)");
            p.photometry = web;
            p.nadir = l.nadir;
            p.c0 = l.c0;
            p.intensity = l.color;
            p.photometricScale = (l.fluxLm ? *l.fluxLm / fileFlux : 1.0) * l.dimming * l.maintenance;
            p.photometricFlux = p.photometricScale * fileFlux;
            if (!l.pointSource) addOpening(p, *web);
            return p;
        }
        if (l.kind == LightKind::Spot) {
            p.isSpot = true;
            p.direction = l.direction;
            p.cosInner = std::cos(glm::radians(l.innerAngleDeg));
            p.cosOuter = std::cos(glm::radians(l.outerAngleDeg));
            if (p.cosInner - p.cosOuter < 1e-12) p.cosInner = p.cosOuter + 1e-12;  // hard-edged spot
        }
        return p;
    }

    /// The luminous opening as a grid of up to kOpeningParts × kOpeningParts equal parts (a
    /// round one: the parts of that grid inside the circle), in the plane ⟂ nadir, length
    /// along C0.
    static constexpr double kOpeningParts = 4;
    static void addOpening(PointLight& p, const Photometry& web) {
        const double length = web.round ? web.width : web.length, width = web.width;
        p.openingSize = std::max(length, width);
        if (!(p.openingSize > 0)) return;
        const Vec3 c90 = glm::cross(-p.nadir, p.c0);
        const int kl = std::max(1, static_cast<int>(std::lround(kOpeningParts * length / p.openingSize)));
        const int kw = std::max(1, static_cast<int>(std::lround(kOpeningParts * width / p.openingSize)));
        for (int i = 0; i < kl; ++i)
            for (int j = 0; j < kw; ++j) {
                const double u = ((i + 0.5) / kl - 0.5) * length, v = ((j + 0.5) / kw - 0.5) * width;
                if (web.round && u * u + v * v > 0.25 * width * width) continue;
                p.openingPoints.push_back(p.position + u * p.c0 + v * c90);
            }
    }

    /// A camera in world space; one "from_sensor" stands at the sensor (1 mm off its surface)
    /// and looks along its normal.
    Camera camera(const Scene& s, const CameraDesc& c) const {
        Camera cam{c.position, c.lookAt, c.up, c.verticalFovDeg, c.width, c.height, c.projection, c.orthoHeight};
        if (c.fromSensor.empty()) return cam;
        const auto it =
            std::find_if(s.sensors.begin(), s.sensors.end(), [&](const Sensor& x) { return x.name == c.fromSensor; });
        if (it == s.sensors.end()) fail(c.where + "/from_sensor", "no sensor \"" + c.fromSensor + "\" in the scene");
        cam.position = it->position + 1e-3 * it->normal;
        cam.lookAt = cam.position + it->normal;
        cam.up = std::abs(it->normal.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(0, 0, -1);
        return cam;
    }

    /// The walkthrough's frames; a path that does not move or turns a frame to look
    /// along its up vector is an error at the path.
    std::vector<Camera> pathFrames(const Scene& s, const CameraPathDesc& path) const {
        std::vector<Camera> keys;
        for (const auto& k : path.keyframes) keys.push_back(camera(s, k));
        try {
            return framesAlongPath(keys, path.frames);
        } catch (const std::invalid_argument& e) {
            fail(path.where, e.what());
        }
    }

    /// The surface grids' points, after the sensors; a name used twice is an error. The
    /// parser checked the file's sensors, so a name used again is a surface grid's.
    void addSurfaceGrids(Scene& s) {
        if (m_desc.surfaceGrids.empty()) return;
        std::vector<size_t> begin;  // per surface grid, its first point's index
        for (const auto& grid : m_desc.surfaceGrids) {
            begin.push_back(s.sensors.size());
            for (auto& sensor : surfaceGridSensors(s, grid)) s.sensors.push_back(std::move(sensor));
        }
        const std::vector<size_t> again = sensorsNamedAgain(s.sensors);
        if (again.empty()) return;
        const size_t grid = std::upper_bound(begin.begin(), begin.end(), again.front()) - begin.begin() - 1;
        fail(m_desc.surfaceGrids[grid].where + "/name",
             fmt::format("sensor name \"{}\" is used twice", s.sensors[again.front()].name));
    }

    /// The scene's bounding box; every surface (as placed by its transform) and every
    /// mesh file's light must lie within ±kMaxCoordinate, as the scene file's points must.
    static bool beyond(const Vec3& p) { return !(maxAbs(p) <= kMaxCoordinate); }
    void checkWithinRange(const SurfaceGroup& g, const std::string& where) const {
        for (const auto& p : g.positions)
            if (beyond(p))
                fail(where, fmt::format("the surface reaches ({:.3g}, {:.3g}, {:.3g}) m, beyond ±1e9 m "
                                        "(is its transform's scale or the file's unit wrong?)",
                                        p.x, p.y, p.z));
    }
    void computeBounds(Scene& s) const {
        Vec3 lo(1e300), hi(-1e300);
        for (const auto& g : s.groups) {
            checkWithinRange(g, g.where);
            for (const auto& p : g.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        for (const auto& l : m_fileLights)
            if (beyond(l.position)) fail(l.where, "the light lies beyond ±1e9 m");
        s.boundsMin = lo;
        s.boundsMax = hi;
    }

    const SceneDesc& m_desc;
    std::map<std::string, int> m_fileMaterials;  ///< "<file>:<material>" → scene material
    std::vector<PointLight> m_fileLights;        ///< punctual lights of mesh files, world space
    std::map<std::string, std::shared_ptr<const Photometry>> m_photometry;  ///< by file: read once
};

}  // namespace

Scene buildScene(const SceneDesc& desc) {
    return Builder(desc).build();
}

}  // namespace rayrad::scene
