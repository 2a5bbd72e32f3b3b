// rayrad validate glare: the glare formulas, the CIE 190 UGR table and a fisheye's figures
// against references — hand computations, CIE 117's and CIE 190's printed values, the
// tables of DIALux and Relux, exact cones — and UGR at an observer against the table.
#pragma once

#include <app/glare/fisheye_glare.h>
#include <app/glare/ugr_table.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// A UGR table as another program prints it: 19 rows of 10 values in CIE 190's order,
/// nothing where it prints "<10.0". Throws InputError naming the file and line.
using UgrReference = std::vector<std::vector<std::optional<double>>>;
UgrReference readUgrReference(const std::string& path);

/// The largest |ours − reference| over the entries both give; `compared` (if given) gets
/// how many that was.
double largestUgrDifference(const UgrTable& ours, const UgrReference& reference, int* compared = nullptr);

/// CIE 190's standard room 4H × 4H (H = 2 m) as a scene (JSON): floor 0.2, walls 0.5,
/// ceiling 0.7, sixteen of the luminaire `ldtFile` at spacing 1 H 1 cm below the ceiling,
/// C0 along the line of sight (crosswise), one observer "eye" seated at the middle of a
/// wall looking along +z (y up). `partition`: a wall from floor to ceiling 0.4 m in front
/// of the eye hides the luminaires on its right (x > 0).
std::string ugrStandardRoomJson(const std::string& ldtFile, bool partition);

/// A 601² fisheye: 100 cd/m² everywhere and a round source of `luminance`, 5° in radius,
/// 20° up and 10° aside (`centre`); what analyseFisheye finds beside the exact figures: the
/// cone's solid angle 2π(1 − cos α), E_v = π L_bg + ΔL cos θ_c π sin² α, and DGP and UGR of
/// the exact source (L_b from E_v less the source's part).
struct SyntheticFisheye {
    SyntheticFisheye();
    static constexpr double luminance = 20000;  ///< cd/m²
    Vec3 centre{0, 0, 1};
    FisheyeGlare found;
    double omega = 0, ev = 0, dgp = 0, ugr = 0;
};

/// Prints a Markdown table, one line per check with its error, its bound and its run time.
/// Returns the exit code (1 when an error is beyond its bound).
int validateGlare();

}  // namespace rayrad::app
