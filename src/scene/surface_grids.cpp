#include <scene/surface_grids.h>

#include <core/input_error.h>
#include <scene/polygon.h>
#include <scene/sensor_parser.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace rayrad::scene {

namespace {

/// Faces whose normals differ by less than this lie in one plane (with the offset test).
const double kSameNormalCos = std::cos(glm::radians(1.0));
/// `facing`: faces whose normal is within this of the given direction.
const double kFacingCos = std::cos(glm::radians(10.0));
/// Corners closer than this (m) are shared; faces closer than this to a plane lie in it.
constexpr double kPlaneTolerance = 1e-4;
/// More points than this in one surface grid is a mistake in the spacing.
constexpr size_t kMaxPoints = 1'000'000;

struct Face {
    std::vector<Vec3> corners;
    Vec3 normal;
};

/// The faces of one material (facing the given way), world space.
std::vector<Face> facesOf(const Scene& scene, const SurfaceGridDesc& grid) {
    std::vector<Face> faces;
    for (const auto& g : scene.groups) {
        if (scene.materials[g.material].name != grid.material) continue;
        for (const auto& poly : g.polygons) {
            Face f;
            for (uint32_t i : poly) f.corners.push_back(g.positions[i]);
            f.normal = polygonNormal(f.corners);
            if (glm::length(f.normal) == 0) continue;  // degenerate
            if (grid.facing && glm::dot(f.normal, *grid.facing) < kFacingCos) continue;
            faces.push_back(std::move(f));
        }
    }
    return faces;
}

/// Groups faces into surfaces: one plane (normal and offset) and connected through shared
/// corners. Returns the surfaces as lists of face indices, in the order of their first face.
std::vector<std::vector<size_t>> surfacesOf(const std::vector<Face>& faces) {
    std::vector<size_t> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    // Faces meet where they share a corner (positions quantised to the tolerance) and lie in
    // one plane.
    std::map<std::array<long long, 3>, std::vector<size_t>> byCorner;
    for (size_t f = 0; f < faces.size(); ++f)
        for (const auto& c : faces[f].corners) {
            std::array<long long, 3> key;
            for (int a = 0; a < 3; ++a) key[a] = std::llround(c[a] / kPlaneTolerance);
            byCorner[key].push_back(f);
        }
    for (const auto& [corner, list] : byCorner)
        for (size_t k = 1; k < list.size(); ++k) {
            const Face &a = faces[list[0]], &b = faces[list[k]];
            const bool coplanar = glm::dot(a.normal, b.normal) >= kSameNormalCos &&
                                  std::abs(glm::dot(a.normal, b.corners[0] - a.corners[0])) <= kPlaneTolerance;
            if (coplanar) parent[root(list[k])] = root(list[0]);
        }
    std::vector<std::vector<size_t>> surfaces;
    std::map<size_t, size_t> indexOfRoot;
    for (size_t f = 0; f < faces.size(); ++f) {
        auto [it, added] = indexOfRoot.emplace(root(f), surfaces.size());
        if (added) surfaces.emplace_back();
        surfaces[it->second].push_back(f);
    }
    return surfaces;
}

}  // namespace

std::vector<Sensor> surfaceGridSensors(const Scene& scene, const SurfaceGridDesc& grid) {
    auto fail = [&](const std::string& key, const std::string& what) {
        throw InputError(placeMessage(scene.file, grid.where + (key.empty() ? "" : "/" + key), what));
    };
    const bool known = std::any_of(scene.materials.begin(), scene.materials.end(),
                                   [&](const Material& m) { return m.name == grid.material; });
    if (!known) {
        std::string names;
        for (const auto& m : scene.materials) names += (names.empty() ? "" : ", ") + m.name;
        fail("material", fmt::format("no material \"{}\" in the scene (it has: {})", grid.material, names));
    }
    const std::vector<Face> faces = facesOf(scene, grid);
    if (faces.empty())
        fail(grid.facing ? "facing" : "material", fmt::format("no face of material \"{}\"{}", grid.material,
                                                               grid.facing ? " faces that way (within 10°)" : ""));
    // The surfaces large enough for a grid.
    std::vector<std::vector<size_t>> surfaces;
    for (auto& surface : surfacesOf(faces)) {
        double area = 0;
        for (size_t f : surface) area += polygonArea(faces[f].corners);
        if (area >= grid.minArea) surfaces.push_back(std::move(surface));
    }
    if (surfaces.empty())
        fail("min_area", fmt::format("no surface of \"{}\" has {:g} m² or more", grid.material, grid.minArea));
    std::vector<Sensor> out;
    for (size_t k = 0; k < surfaces.size(); ++k) {
        const std::string name = surfaces.size() == 1 ? grid.name : fmt::format("{}#{}", grid.name, k + 1);
        // The plane's axes: world x (or z) in the plane, and u × n (on a floor or desk top
        // i runs along x and j along z, as on a work plane).
        const Face& first = faces[surfaces[k][0]];
        const Vec3 n = first.normal;
        const Vec3 axis = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 0, 1);
        const Vec3 u = glm::normalize(axis - glm::dot(axis, n) * n), v = glm::cross(u, n);
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (size_t f : surfaces[k])
            for (const auto& c : faces[f].corners) {
                const double p[2] = {glm::dot(c, u), glm::dot(c, v)};
                for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
            }
        const double extent[2] = {hi[0] - lo[0], hi[1] - lo[1]};
        const double spacing = grid.spacing.value_or(standardGridSpacing(std::max(extent[0], extent[1])));
        int count[2];  // a mesh's float corners make 1.2 m read 1.2000000477 m: not a 13th cell
        for (int a = 0; a < 2; ++a) count[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / spacing - 1e-6)));
        if (static_cast<double>(count[0]) * count[1] + static_cast<double>(out.size()) > kMaxPoints)
            fail("spacing", fmt::format("a spacing of {:g} m puts more than {} points on the faces of \"{}\"", spacing,
                                        kMaxPoints, grid.material));
        const double planeOffset = glm::dot(n, first.corners[0]);
        for (int j = 0; j < count[1]; ++j)
            for (int i = 0; i < count[0]; ++i) {
                const double a = lo[0] + (i + 0.5) / count[0] * extent[0], b = lo[1] + (j + 0.5) / count[1] * extent[1];
                const Vec3 x = a * u + b * v + planeOffset * n;
                const bool on = std::any_of(surfaces[k].begin(), surfaces[k].end(),
                                            [&](size_t f) { return polygonContains(faces[f].corners, faces[f].normal, x); });
                if (!on) continue;
                Sensor s;
                s.name = fmt::format("{}[{},{}]", name, i, j);
                s.grid = name;
                s.gridU = i, s.gridV = j;
                s.position = x + grid.offset * n;
                s.normal = n;
                out.push_back(std::move(s));
            }
    }
    if (out.empty())
        fail("spacing", fmt::format("no grid point falls on a face of \"{}\": give a smaller spacing", grid.material));
    return out;
}

}  // namespace rayrad::scene
