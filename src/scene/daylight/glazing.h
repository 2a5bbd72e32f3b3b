// Clear glazing: how its transmittance falls off with the angle of incidence.
#pragma once

namespace rayrad::scene {

/// The refractive index of the clear float glass the angle dependence is taken from.
constexpr double kGlazingIndex = 1.52;

/// Transmittance of a glazing of normal transmittance `normal` (0, 1] at the angle of
/// incidence θ (cosθ given): τ(θ) = normal · g(θ) / g(0), with g the transmittance of one
/// pane of clear glass (index kGlazingIndex) whose internal transmittance T_a is chosen so
/// that g(0) matches `normal` (or T_a = 1 when no pane transmits that much):
///   g(θ) = ½ Σ_{s,p} (1 − R)² T / (1 − R² T²),  T = T_a^{1/cosθ_t},
/// R the Fresnel reflectance of each polarisation, θ_t the refracted angle (light
/// reflected back and forth inside the pane included). normal = 1: an open hole, 1 at
/// every angle.
double glazingTransmittance(double normal, double cosTheta);

}  // namespace rayrad::scene
