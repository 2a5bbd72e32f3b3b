// The daylight's account: the light the room reflects back out through its openings.
#pragma once

#include <core/visibility.h>
#include <radiosity/direct/direct_light.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

namespace rayrad::radiosity {

/// lm that leaves the scene again: Σ_i ρ_i (Ē_dir + E_ind)_i A_i (F_i→openings + F_i→sky),
/// each patch's reflected flux times the form factor from its centroid to each opening,
/// shadowed (16 shadow rays), and the fraction of 16 stratified cosine-distributed rays that
/// reach the open sky past every opening (outdoor surfaces). With the absorbed flux it closes
/// the daylight's account: what came in = absorbed + left again. 0 without openings.
double leavingThroughOpenings(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                              const DirectLight& lights, const Visibility& vis);

}  // namespace rayrad::radiosity
