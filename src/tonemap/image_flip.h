// ꟻLIP (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild, "FLIP: A Difference
// Evaluator for Alternating Images", HPG 2020), the LDR version: how different two displayed
// images look when flipped between, per pixel in [0, 1]. Written here from the paper.
#pragma once

#include <core/math.h>

#include <vector>

namespace rayrad::tonemap {

/// Pixels per degree of visual angle for a 0.7 m wide 4K display seen from 0.7 m (the
/// paper's default, ≈ 67).
constexpr double kFlipPixelsPerDegree = 0.7 * 3840 / 0.7 * kPi / 180;

/// The per-pixel ꟻLIP error of `test` against `reference`: linear Rec.709 colours as a
/// display shows them, each channel in [0, 1] (clamped), row-major, width × height.
/// Colour pipeline: YCxCz, each channel filtered by its contrast sensitivity function (sums
/// of Gaussians, radius 3σ of the widest), back to linear RGB clamped to [0, 1], CIELAB with
/// Hunt's adjustment, HyAB distance ^ q_c (0.7), redistributed onto [0, 1] (p_c 0.4, p_t 0.95,
/// c_max the green–blue distance). Feature pipeline: edges and points of the normalised
/// luminance (first and second derivative of a Gaussian, σ = 0.5 · 0.082 · ppd, positive and
/// negative weights each summing to 1), ΔE_f = (max of the edge and point magnitude
/// differences / √2) ^ q_f (0.5). Result ΔE_c ^ (1 − ΔE_f). Borders are replicated.
std::vector<double> flipErrorMap(const std::vector<Rgb>& reference, const std::vector<Rgb>& test, int width, int height,
                                 double pixelsPerDegree = kFlipPixelsPerDegree);

}  // namespace rayrad::tonemap
