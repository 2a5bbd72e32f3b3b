// rayrad validate daylight: the sun, the skies and the light through openings against
// references computed here, independently of the code under test.
#pragma once

#include <scene/daylight/daylight.h>

namespace rayrad::app {

/// ∫ L cos Z dω over the sky (lx) by the midpoint rule in zenith angle and azimuth
/// (dω = sin Z dZ dφ, 900 × 1800 cells): a reference apart from
/// SkyDistribution::horizontalFactor's rule in (cos Z, φ).
double skyOnHorizontalPlane(const scene::Daylight& d);

/// Prints a Markdown table, one line per check with its error, its bound and its run time:
/// the sun's position against the worked example of NREL's Solar Position Algorithm paper
/// (Reda & Andreas 2008); the 15 CIE standard skies' relative luminance at sky points
/// against the standard's formulas; the uniform sky through a square roof opening against
/// π L F (F by the corner formula); the CIE overcast sky through a vertical window, and a
/// glazed one, against a midpoint quadrature; the sun on a tilted plane against E_n cos i;
/// the Perez sky's scale (skyOnHorizontalPlane against E_dh) and its illuminance input.
/// Returns the exit code (1 when an error is beyond its bound).
int validateDaylight();

}  // namespace rayrad::app
