// Cluster→cluster transfer: the illuminance a receiver cluster gets per unit source luminance.
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters.h>
#include <radiosity/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// π F(dA_D → C) · V(C, D) in lx per cd/m²: the illuminance at the receiver cluster's
/// centroid (with its mean normal) from the source cluster at unit luminance.
/// Adaptive accuracy instead of a deeper hierarchy: far away (beyond 4 source
/// diameters) the point approximation A_C cosθ_C cosθ_D / (π r²); nearer, the sum of the
/// member patches' form factors (each analytic when close). V is the visible fraction of
/// up to four rays between the clusters' sample patches. Deterministic: the energy
/// correction repeats it exactly to reconstruct what earlier shots delivered.
double clusterTransfer(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, const Visibility& vis,
                       double analyticDistance);

/// How a cluster→cluster shot from `source` is shared among the receiver's patches:
/// shape[k] multiplies the cluster-level illuminance for member k, with area-weighted
/// mean 1 (so the flux is the cluster-level flux). `detail` false: all 1 (uniform, the
/// paper). true: proportional to the point kernel max(0, cosθ_k) max(0, cosθ_C) / r_k²
/// from the source cluster's centroid (uniform if that vanishes everywhere).
void receiverShape(const PatchMesh& mesh, const Cluster& source, const Cluster& receiver, bool detail,
                   std::vector<double>& shape);

}  // namespace rayrad::radiosity
