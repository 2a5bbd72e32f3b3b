// Planar polygon helpers: normal, area, planarity, convexity, triangulation.
#pragma once

#include <core/math.h>

#include <array>
#include <vector>

namespace rayrad::scene {

/// Unit normal by Newell's method (robust for nearly degenerate and non-planar input);
/// right-handed with the vertex order. Zero vector for a degenerate polygon.
Vec3 polygonNormal(const std::vector<Vec3>& v);
/// Area in m² (of the projection onto the Newell plane).
double polygonArea(const std::vector<Vec3>& v);
double polygonArea(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices);
/// Largest distance of a vertex from the polygon's mean plane, in metres.
double maxPlaneDistance(const std::vector<Vec3>& v);
/// True when every corner turns the same way around `normal`.
bool isConvexAround(const std::vector<Vec3>& v, const Vec3& normal);
/// True when p (a point in the polygon's plane) lies inside the polygon: the crossing
/// rule in the projection that drops the normal's largest axis.
bool polygonContains(const std::vector<Vec3>& v, const Vec3& normal, const Vec3& p);
/// Distance in metres between segment ab and a convex planar polygon (0 when the
/// segment crosses it). The closest pair lies at a crossing, at an end of the segment
/// against the polygon's face, or between the segment and an edge.
double segmentPolygonDistance(const Vec3& a, const Vec3& b, const std::vector<Vec3>& v, const Vec3& normal);
/// Distance in metres between segments pq and rs.
double segmentDistance(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s);
/// Ear-clipping triangulation of a simple planar polygon; indices into v.
std::vector<std::array<uint32_t, 3>> triangulate(const std::vector<Vec3>& v);
/// Whether the triangles (indices into `positions`) lie in one plane and face one way:
/// every vertex within 10⁻⁶ of their extent of the first triangle's plane, every normal
/// within 1° of its normal.
bool trianglesInOnePlane(const std::vector<Vec3>& positions, const std::vector<std::vector<uint32_t>>& triangles);

}  // namespace rayrad::scene
