// The validated scene in world space: surfaces, materials, lights, camera, sensors.
#pragma once

#include <core/math.h>
#include <core/texture_source.h>
#include <scene/photometry.h>
#include <scene/scene_desc.h>
#include <scene/settings.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::scene {

/// A Lambertian material (`emission` non-zero for area lights), or a specular one: a
/// mirror (specular reflectance Ks, front side only) or glass (a clear dielectric).
/// Specular surfaces get no radiosity patches: mirrors act through the image method,
/// glass only in the ray tracer.
struct Material {
    std::string name;
    SurfaceKind kind = SurfaceKind::Diffuse;
    Rgb reflectance{0.0};  ///< diffuse reflectance per channel, in [0, 1)
    Rgb emission{0.0};     ///< emitted luminance per channel, cd/m² (front side only)
    Rgb specular{0.0};     ///< mirror: Ks per channel, in [0, 1]
    double ior = 1.5;      ///< glass: index of refraction
    double transmittance = 1.0;  ///< opening: normal transmittance (1: an unglazed hole)
    /// One side of a two-sided diffuse surface: the builder adds the back as a coincident
    /// reversed surface (the ray tracer shows whichever side's front faces the ray).
    bool twoSided = false;
    std::string lightGroup;  ///< emissive: the light group it belongs to ("" none)
    /// Diffuse: index into Scene::textures (−1 none). Then ρ(x) = reflectance · T(u, v),
    /// clamped to kMaxFileReflectance: `reflectance` is the texture's multiplier.
    int texture = -1;
    bool isEmissive() const { return emission.r > 0 || emission.g > 0 || emission.b > 0; }
    bool isDiffuse() const { return kind == SurfaceKind::Diffuse; }
    bool isOpening() const { return kind == SurfaceKind::Opening; }
};

/// One planar mirror polygon: reflects across its plane n·x = offset, front side only.
struct Mirror {
    std::vector<Vec3> polygon;  ///< CCW seen from the front
    Vec3 normal{0.0};           ///< unit, front side
    double offset = 0;          ///< n·x on the plane, m
    Rgb specular{0.0};          ///< Ks
    std::string where;          ///< JSON pointer of the object

    double side(const Vec3& p) const { return glm::dot(normal, p) - offset; }  ///< signed distance, m
    Vec3 reflectPoint(const Vec3& p) const { return p - 2.0 * side(p) * normal; }
    Vec3 reflectDirection(const Vec3& d) const { return d - 2.0 * glm::dot(d, normal) * normal; }
    /// Whether light can pass between this mirror and a point p of a planar surface with
    /// unit normal n: p in front of the mirror, and some of the polygon in front of the
    /// surface's plane (light leaves and arrives through its front hemisphere only; the
    /// same for every point of the plane's surface on the mirror's front).
    bool facedBy(const Vec3& p, const Vec3& n) const {
        if (side(p) <= 0) return false;
        for (const Vec3& v : polygon)
            if (glm::dot(n, v - p) > 0) return true;
        return false;
    }
};

/// Polygons that share vertices: one quad, one face of a box, a whole sphere or mesh.
/// Vertex values (indirect light) are averaged only within a group.
struct SurfaceGroup {
    std::vector<Vec3> positions;                  ///< world space, metres
    std::vector<std::vector<uint32_t>> polygons;  ///< indices, CCW seen from the front
    /// Texture coordinates of each polygon's corners, in its order (empty: none); a mesh's
    /// seams keep their own coordinates on each side.
    std::vector<std::vector<glm::dvec2>> polygonUvs;
    int material = 0;
    std::string where;  ///< JSON pointer of the object
};

/// A point light or a spot, in candela. I(θ) = intensity for θ ≤ inner, a smooth step
/// down to 0 at the outer angle (spots); isotropic for points.
/// A luminaire is a point source beyond this many times its opening's size, an area source
/// (its opening, each part with the distribution) within.
constexpr double kNearFieldSizes = 5.0;

struct PointLight {
    Vec3 position{0.0};
    Rgb intensity{0.0};  ///< cd per channel on the axis (luminance-weighted Y = given cd)
    bool isSpot = false;
    Vec3 direction{0, 0, -1};
    double cosInner = -1, cosOuter = -1;
    std::string where;       ///< JSON pointer (or mesh file) it came from, for messages
    std::string lightGroup;  ///< the light group it belongs to ("" none)
    /// A luminaire: its measured distribution (shared by the lights of one file), its
    /// axes in the scene (nadir: γ = 0; c0: the C0 plane, ⟂ nadir; C90 = (−nadir) × c0,
    /// so C grows counter-clockwise seen from above), the factor on the file's candela
    /// (flux scaling × dimming × maintenance) and the flux that makes, lm. `intensity`
    /// is then the colour, luminance 1. A point source at its photometric centre.
    std::shared_ptr<const Photometry> photometry;
    Vec3 nadir{0, -1, 0}, c0{1, 0, 0};
    double photometricScale = 1;
    double photometricFlux = 0;
    /// A luminaire's luminous opening (the file's width and length, in the plane ⟂ nadir
    /// through `position`) as a grid of equal parts, world space; empty without one.
    /// Within kNearFieldSizes of its size the light leaves from these points, each with
    /// 1/n of the distribution; farther, from `position`.
    std::vector<Vec3> openingPoints;
    double openingSize = 0;  ///< m, the opening's larger dimension

    /// Intensity in cd (RGB) toward the unit direction `w` (from the light).
    Rgb intensityToward(const Vec3& w) const;
};

struct Camera {
    Vec3 position{0.0}, lookAt{0, 0, -1}, up{0, 1, 0};
    double verticalFovDeg = 45;
    int width = 512, height = 512;
    Projection projection = Projection::Perspective;
    double orthoHeight = 0;  ///< m, orthographic only
};

/// A named view of the scene (render --camera NAME).
struct View {
    std::string name;
    Camera camera;
};

struct Sensor {
    std::string name;
    std::string grid;            ///< the sensor grid it is a point of ("" for a single sensor)
    int gridU = -1, gridV = -1;  ///< its cell in the grid (u along the first axis)
    Vec3 position{0.0};
    Vec3 normal{0, 0, 1};
    std::optional<double> refDirect, refIndirect, refTotal;  ///< lx
};

/// Reflectances read from mesh files are clamped to this (a white of 1 never converges).
constexpr double kMaxFileReflectance = 0.95;

/// Counts of what the builder dropped, reported as warnings.
struct BuildWarnings {
    int degeneratePolygons = 0;
    int droppedMeshFaces = 0;                  ///< points, lines and faces with bad indices in mesh files
    int clampedFileReflectances = 0;           ///< mesh-file materials whose reflectance was clamped
    /// What the mesh files bring that rayrad reads otherwise than meant, one line each (a
    /// texture or .mtl missing, glTF properties it cannot honour, a size suggesting another unit).
    std::vector<std::string> fileWarnings;
};

/// The validated scene in world space, with its settings (scene.shooting, scene.render …).
struct Scene : Settings {
    std::string file;
    std::vector<Material> materials;
    std::vector<std::string> textures;  ///< image files of the materials' textures (Material::texture)
    /// The texture images, opened (the app opens them after building: scene holds no image
    /// library); null when the scene has none.
    std::shared_ptr<const TextureSource> textureImages;
    std::vector<SurfaceGroup> groups;
    std::vector<PointLight> lights;
    std::vector<Mirror> mirrors;     ///< every polygon of every mirror surface
    std::optional<Camera> camera;    ///< the view being rendered (the default, or the one chosen)
    std::vector<View> views;         ///< every named view
    std::vector<Camera> pathFrames;  ///< the walkthrough's frames ("camera_path"), in order
    std::vector<Sensor> sensors;
    std::optional<Daylight> daylight;  ///< the sky and the sun, lighting through the openings
    std::vector<Observer> observers;   ///< eyes where glare is reported
    BuildWarnings warnings;

    /// Axis-aligned bounds of all geometry.
    Vec3 boundsMin{0.0}, boundsMax{0.0};
    double diagonal() const { return glm::length(boundsMax - boundsMin); }
    size_t polygonCount() const;
    bool hasReflectance() const;
    bool isPatchSurface(const SurfaceGroup& g) const { return materials[g.material].isDiffuse(); }
};

/// Builds world-space geometry (transforms, boxes, spheres, meshes through assimp) and
/// resolves material names. Throws InputError naming the file and place for problems
/// found here (missing mesh file, area light of zero area, ...).
Scene buildScene(const SceneDesc& desc);

}  // namespace rayrad::scene
