// `rayrad info LUMINAIRE.ies|.ldt`: what a photometric file says and what its table
// integrates to, so a designer can check a file before using it.
#pragma once

#include <scene/photometry.h>

#include <string>

namespace rayrad::app {

/// The report: format, type, symmetry and grid, stated lamp flux, integrated flux, light
/// output ratio (integrated and, for EULUMDAT, stated), peak intensity and its direction,
/// the luminous opening, watts, tilt.
std::string photometryReport(const scene::Photometry& p);

}  // namespace rayrad::app
