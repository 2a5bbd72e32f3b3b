// The scene file as plain data: what the parser returns, before any geometry is built.
#pragma once

#include <core/math.h>
#include <scene/daylight/daylight.h>
#include <scene/observers.h>
#include <scene/settings.h>

#include <glm/mat4x4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::scene {

/// Diffuse (Lambertian), a planar mirror, clear glass (ray tracer only), or an opening:
/// a window or skylight the daylight enters through (no surface for visibility; glazed
/// when its transmittance is below 1).
enum class SurfaceKind { Diffuse, Mirror, Glass, Opening };

/// A Lambertian material, optionally emissive (an area light); or a planar mirror or
/// glass (specular, for the image method and the ray tracer).
struct MaterialDesc {
    std::string name;
    std::string where;  ///< JSON pointer, for messages
    SurfaceKind kind = SurfaceKind::Diffuse;
    Rgb reflectance{0.0};  ///< diffuse reflectance per channel, in [0, 1)
    Rgb specular{0.0};     ///< mirror: specular reflectance Ks per channel, in [0, 1]
    double ior = 1.5;      ///< glass: index of refraction
    double transmittance = 1.0;  ///< opening: normal transmittance of its glazing (1: unglazed)
    bool emissive = false;
    Rgb color{1.0};                      ///< emission colour (scaled to the given luminance)
    double luminance = 0.0;              ///< emitted luminance Y in cd/m² (if given)
    double flux = 0.0;                   ///< total emitted flux in lm (if given instead)
    bool twoSided = false;               ///< diffuse: both sides reflect (else the back is black)
    std::optional<Rgb> backReflectance;  ///< two-sided: the back's reflectance (default: the front's)
    std::string lightGroup;              ///< emissive: the light group it belongs to ("" none)
    /// Diffuse: an image whose colour multiplies the reflectance, ρ(x) = reflectance · T(u, v)
    /// (the product clamped to kMaxFileReflectance); "" none.
    std::string texture;
    std::string resolvedTexture;     ///< relative to the working directory
    glm::dvec2 textureRepeat{1, 1};  ///< quads and box faces: the image repeats this often across a face
};

enum class ObjectKind { Quad, Polygon, Box, Sphere, Mesh };

struct ObjectDesc {
    ObjectKind kind = ObjectKind::Quad;
    std::string where;  ///< JSON pointer, for messages
    std::string material;
    std::vector<Vec3> vertices;  ///< quad/polygon, CCW seen from the lit side
    Vec3 boxMin{0.0}, boxMax{0.0};
    Vec3 center{0.0};
    double radius = 1.0;
    int subdivisions = 8;  ///< sphere: 12·n² triangles (a projected cube)
    bool inward = false;   ///< box/sphere: normals face the inside
    /// sphere/mesh: keep only triangles with every vertex on the side n·x ≥ offset of
    /// each plane (n, offset), world space; cuts a hemisphere or a quarter sphere.
    std::vector<std::pair<Vec3, double>> keepAbove;
    std::string file;           ///< mesh: path as written in the scene file
    std::string resolvedFile;   ///< mesh: path relative to the working directory
    /// mesh: metres per unit of the file ("units": "mm" 0.001, "cm", "in", "ft", "m"),
    /// applied before the transform; 0 when not given (metres, and a size check).
    double fileUnit = 0;
    glm::dmat4 transform{1.0};  ///< object → world
};

enum class LightKind { Point, Spot, Luminaire };

struct LightDesc {
    LightKind kind = LightKind::Point;
    std::string where;
    Vec3 position{0.0};
    Rgb color{1.0};               ///< scaled so its luminance weight is 1
    double intensity = 0.0;       ///< cd (on the axis for a spot)
    Vec3 direction{0, 0, -1};     ///< spot axis
    double innerAngleDeg = 30.0;  ///< spot: full intensity inside this half-angle
    double outerAngleDeg = 45.0;  ///< spot: zero beyond this half-angle
    // Luminaire: a photometric file, aimed.
    std::string file;              ///< as written in the scene
    std::string resolvedFile;      ///< relative to the working directory
    Vec3 nadir{0, -1, 0};          ///< unit: where the luminaire's γ = 0 points
    Vec3 c0{1, 0, 0};              ///< unit, ⟂ nadir: the direction of its C0 plane
    std::optional<double> fluxLm;  ///< scale the file's table to this flux
    double dimming = 1.0;          ///< × the light, (0, 1]
    double maintenance = 1.0;      ///< light-loss factor, (0, 1]
    bool pointSource = false;      ///< ignore the file's opening: a point source at any distance
    std::string lightGroup;        ///< the light group it belongs to ("" none)
};

struct CameraDesc {
    std::string where;  ///< JSON pointer, for messages
    Vec3 position{0.0};
    Vec3 lookAt{0, 0, -1};
    Vec3 up{0, 1, 0};
    double verticalFovDeg = 45.0;
    int width = 512;
    int height = 512;
    Projection projection = Projection::Perspective;
    double orthoHeight = 0;  ///< m (orthographic)
    std::string fromSensor;  ///< placed at this sensor, looking along its normal (the builder resolves it)
};

/// A walkthrough: keyframes (position, look_at, up, vfov_deg; the resolution is the
/// path's) and how many frames to make along them (scene/camera_path.h interpolates).
struct CameraPathDesc {
    std::string where;  ///< JSON pointer, for messages
    int frames = 2;
    std::vector<CameraDesc> keyframes;
};
constexpr int kMaxPathFrames = 100'000;

/// A point where illuminance is reported, with optional references in lx.
struct SensorDesc {
    std::string name;
    std::string grid;            ///< the sensor grid it is a point of ("" for a single sensor)
    int gridU = -1, gridV = -1;  ///< its cell in the grid (u along the first axis)
    Vec3 position{0.0};
    Vec3 normal{0, 0, 1};
    std::optional<double> refDirect, refIndirect, refTotal;
};

/// A grid on surfaces of the scene: every planar face of one material (facing a given
/// way, if asked), a grid of points on each plane they make (expanded by the builder,
/// which knows the geometry).
struct SurfaceGridDesc {
    std::string where;  ///< JSON pointer, for messages
    std::string name;
    std::string material;           ///< a scene material, or "<mesh file>:<material>"
    std::optional<Vec3> facing;     ///< keep faces whose normal is within 10° of this
    std::optional<double> spacing;  ///< m; none: EN 12464-1's p = 0.2 · 5^log10(d) per plane
    double offset = 0;              ///< m, the points' height above the surface
    double minArea = 0.01;          ///< m²: smaller surfaces (a leg's end, a seam) get no grid
};

/// The scene file as plain data, with its settings (desc.meshing, desc.render …).
struct SceneDesc : Settings {
    std::string file;  ///< the scene file's path, for messages
    std::vector<MaterialDesc> materials;
    std::vector<ObjectDesc> objects;
    std::vector<LightDesc> lights;
    std::optional<CameraDesc> camera;  ///< the default view: "camera", else the first of "cameras"
    /// Every view by name, in the file's order: "camera" (named "camera"), then "cameras".
    std::vector<std::pair<std::string, CameraDesc>> views;
    std::optional<CameraPathDesc> cameraPath;   ///< "camera_path": a walkthrough's frames
    std::vector<SensorDesc> sensors;            ///< points, with grids already expanded
    std::vector<SurfaceGridDesc> surfaceGrids;  ///< expanded into sensors by the builder
    std::optional<Daylight> daylight;           ///< "daylight": the sky and the sun
    std::vector<Observer> observers;            ///< "observers": eyes where glare is reported
};

}  // namespace rayrad::scene
