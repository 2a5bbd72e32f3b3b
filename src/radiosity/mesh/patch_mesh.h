// Radiosity patches: the premeshed triangles of every input surface.
#pragma once

#include <core/math.h>
#include <core/visibility.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace rayrad::radiosity {

/// One triangle of the premeshed scene. Vertices are shared only inside one surface
/// group (one quad, one box face, one sphere or mesh), so vertex averaging never mixes
/// walls that meet at an edge.
struct Patch {
    std::array<uint32_t, 3> v{};  ///< indices into PatchMesh::vertices, CCW seen from the front
    Vec3 normal{0.0};             ///< unit, front side
    Vec3 centroid{0.0};
    double area = 0;      ///< m²
    double diameter = 0;  ///< longest edge, m
    int material = 0;
    int group = 0;  ///< index of the scene's SurfaceGroup
};

/// Where another surface stands on (or passes through) a patch off the patch's mesh
/// lines: the segment along which it meets the patch's plane (all of it, also beyond the
/// patch), and that surface's front normal.
struct ContactOutline {
    Vec3 a{0.0}, b{0.0};
    Vec3 normal{0.0};
};

struct PatchMesh {
    std::vector<Vec3> vertices;
    std::vector<Patch> patches;
    /// The edge length the premesher aimed for, m (radiosity.max_edge, or its default):
    /// later stages measure "small" against it. 0 for a mesh not made by premesh().
    double edgeLength = 0;
    /// Texture coordinates (v up) of each patch's corners, 3·i + k; empty when the scene
    /// has no textures ((0, 0) for the patches of untextured surfaces).
    std::vector<glm::vec2> cornerUv;
    /// Each patch's reflectance averaged over its texture, ρ · mean T (textureReflectance()
    /// fills it); empty when the scene has no textures. The radiosity uses it; the ray
    /// tracer uses ρ · T at the hit, whose mean over the patch is this.
    std::vector<RgbF> texturedReflectance;
    /// Shading normals of each patch's corners, 3·i + k (computeShadingNormals); empty when
    /// no corner's differs from its patch's normal (flat surfaces only) or smoothing is off.
    std::vector<glm::vec3> cornerNormal;
    /// The contact outlines crossing each patch's interior (findContactOutlines): patch i's
    /// are outlines[outlineBegin[i] .. outlineBegin[i + 1]); outlineBegin is empty when
    /// they were not looked for.
    std::vector<uint32_t> outlineBegin;
    std::vector<ContactOutline> outlines;
    /// Per vertex: 1 when it lies under a surface standing on its patch, inside a closed
    /// solid (under a box: behind every outline crossing its patches, and rays from it
    /// meet only backs). Its value is then gathered at the outline, on the open side, for
    /// the visible part of its triangles (contact_vertices.h).
    std::vector<char> underSolid;
    /// Per patch: 1 when a surface lies just in front of it (covered_patches.h); empty when
    /// not looked for.
    std::vector<char> covered;
    /// Whether patch i is covered (false when coverage was not looked for).
    bool isCovered(size_t i) const { return !covered.empty() && covered[i]; }
    /// Per vertex that an outline crossing one of its patches runs through: the front
    /// normals of those outlines, vertex v's at throughNormals[throughBegin[v] ..
    /// throughBegin[v + 1]). Such a vertex lies on both sides; its value is the light in
    /// front (contact_vertices.h), which no point behind takes (sameSideWeights).
    std::vector<uint32_t> throughBegin;
    std::vector<Vec3> throughNormals;
    /// The front normals of the outlines running through vertex v (none when none does).
    std::pair<const Vec3*, const Vec3*> outlinesThrough(uint32_t v) const {
        if (throughBegin.empty()) return {nullptr, nullptr};
        return {throughNormals.data() + throughBegin[v], throughNormals.data() + throughBegin[v + 1]};
    }

    const Vec3& corner(const Patch& p, int k) const { return vertices[p.v[k]]; }
    /// The point with barycentric coordinates (1-u-v, u, v) on patch p.
    Vec3 pointAt(const Patch& p, double u, double v) const {
        return (1 - u - v) * corner(p, 0) + u * corner(p, 1) + v * corner(p, 2);
    }
    double totalArea() const;
};

/// Per vertex, the patches that have it as a corner (in patch order).
std::vector<std::vector<uint32_t>> patchesAround(const PatchMesh& mesh);
/// Per vertex, the sum of its patches' corner angles there (rad): 2π inside a flat
/// surface (its patches close the fan around it), less on a surface's rim, other on a
/// curved mesh.
std::vector<double> vertexAngleSums(const PatchMesh& mesh);
/// True for an angle sum of 2π (within 10⁻⁶ rad): the vertex's patches close around it.
bool isInnerVertex(double angleSum);

/// Fills normal, centroid, area and diameter from the vertex positions.
void computeGeometry(const PatchMesh& mesh, Patch& p);
/// The same from the three corners, counter-clockwise seen from the front.
void computeGeometry(const std::array<Vec3, 3>& corners, Patch& p);

std::string toString(const Patch& p);

/// Calls visit(i) for the patches i that may lie within `radius` (m) of x: those the
/// spatial index finds (Visibility::patchesNear, "and maybe a few more"), or every patch
/// when there is no index (`spatial` null, or one without).
void forPatchesNear(const PatchMesh& mesh, const Visibility* spatial, const Vec3& x, double radius,
                    const std::function<void(uint32_t)>& visit);

}  // namespace rayrad::radiosity
