// The direct pass over the patches: primary light at centroids and vertices.
#pragma once

#include <functional>

#include <core/visibility.h>
#include <radiosity/direct/direct_light.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

namespace rayrad::radiosity {

/// Fills solution.directCorner (E at each corner) and solution.directMean: the mean
/// direct illuminance over each patch from its centroid and its three corners,
/// (3/4) E(c) + (1/12) Σ E(v_k) — exact for quadratic variation — with each point
/// source's share rescaled so that, unshadowed, it is exact (I Ω / A, Ω the solid angle
/// of the patch). A corner inside a flat part of a surface is evaluated once, at the
/// vertex, for all the patches around it (sharedCorners); other corners are pulled a hair
/// toward their patch's centroid so shadow rays do not start inside a neighbouring wall,
/// and are evaluated per patch. A corner under a solid standing on its patch keeps the
/// light at the nearest point of the outline, in front of the solid (the patch's mean
/// does not change). The backs of one-sided patches
/// are evaluated the same way and what they receive is booked as absorbed
/// (solution.backAbsorbedDirect). Deterministic; parallel. `onProgress` gets the
/// fraction of patches done, from any thread (the caller serialises it).
void computeDirect(const scene::Scene& scene, const PatchMesh& mesh, const DirectLight& lights, const Visibility& vis,
                   int areaSamples, RadiositySolution& solution, const std::function<void(double)>& onProgress = {});

}  // namespace rayrad::radiosity
