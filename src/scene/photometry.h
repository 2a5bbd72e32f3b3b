// A luminaire's measured light distribution (an IES LM-63 or EULUMDAT file): candela on
// a grid of angles, with what the file says about its lamps and its luminous opening.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rayrad::scene {

/// How the angles are measured (IES LM-63 photometric types).
/// C: vertical angle γ from the nadir (0 down, 180 up) and horizontal angle C about the
///    luminaire's vertical axis (C0 along its length): dω = sin γ dγ dC. Almost every
///    indoor and street luminaire.
/// B (floodlights) and A (automotive): the polar axis lies across the beam, the
///    luminaire's width (B) or length (A). H is the angle of a plane through that axis,
///    turned from the nadir (H = 0, the beam's axis); V is the angle within the plane from
///    the nadir side toward the polar axis (−90 to 90): dω = cos V dV dH (CIE 121's
///    B-planes and β angles, IES LM-75).
enum class PhotometricType { C, B, A };

struct Photometry {
    std::string file;             ///< for messages
    std::string format;           ///< "IES LM-63-2002", "IES LM-63-1986", "EULUMDAT", ...
    PhotometricType type = PhotometricType::C;
    /// Vertical angles in degrees, ascending: type C 0–180 (or a part); A/B −90–90 (or 0–90).
    std::vector<double> vertical;
    /// Horizontal angles in degrees, ascending, as stored: one (rotational symmetry), a
    /// quadrant 0–90, a half 0–180 or 90–270, or the full 0–360; types A/B −90–90 or 0–90.
    std::vector<double> horizontal;
    /// candela[h][v]: cd at horizontal angle h, vertical angle v, every factor of the file
    /// applied (candela multiplier, ballast factor; EULUMDAT: cd/klm × lamp flux / 1000 ×
    /// conversion factor).
    std::vector<std::vector<double>> candela;

    /// Lamp flux the file states (lamps × lm per lamp; EULUMDAT: lamp set 1's total), lm;
    /// 0 for absolute photometry (IES lumens −1).
    double lampFlux = 0;
    bool absolute = false;
    std::optional<double> statedLor;  ///< EULUMDAT light output ratio (LORL / 100)
    double inputWatts = 0;
    /// EULUMDAT: how many lamp sets the file lists, and the one used (the first, the
    /// standard set the intensities were measured with): its lamp type and lamp count.
    int lampSets = 0;
    std::string lampType;
    double lampCount = 0;
    /// The luminous opening, m: width (along C90), length (along C0), height. A round
    /// opening has diameter `width` and length 0 (IES writes it as a negative width). An
    /// IES file's length lies along C0; an EULUMDAT file's along C90 (its `width` here).
    double width = 0, length = 0, height = 0;
    bool round = false;
    /// IES TILT: multiplying factors against lamp tilt angle (degrees), when the file
    /// gives them (TILT=INCLUDE or a tilt file); applied at the tilt the file was
    /// measured in, 0°, which is 1 for every file seen so far.
    std::vector<double> tiltAngles, tiltFactors;

    /// I at (vertical, horizontal) angles in degrees (any horizontal angle: the file's
    /// symmetry unfolds it), bilinear in the grid; 0 outside the vertical range.
    double intensity(double verticalDeg, double horizontalDeg) const;
    /// I toward a unit direction given in the luminaire's frame: x along C0 (its length),
    /// y along C90 (its width), z along its axis (the nadir).
    ///   C: γ = acos z, C = atan2(y, x).
    ///   B: V = asin y (toward the width, C90), H = atan2(x, z) (the nadir turned toward C0).
    ///   A: V = asin x (toward the length, C0), H = atan2(y, z) (the nadir turned toward C90).
    double intensityToward(double x, double y, double z) const;
    /// The luminous flux ∫ I dω, lm: I bilinear in the angles, integrated exactly in the
    /// vertical angle (linear I times sin γ, or cos V for types A/B, in closed form) and by
    /// the trapezoid rule across the unfolded horizontal planes.
    double integratedFlux() const;
    /// The largest tabulated intensity (cd) and where it is (degrees).
    struct Peak {
        double candela = 0, verticalDeg = 0, horizontalDeg = 0;
    };
    Peak peak() const;
    /// "rotational", "quadrant (0–90)", "bilateral (0–180)", "bilateral (90–270)", "none (0–360)".
    std::string symmetry() const;
};

/// True for the extensions of photometric files: .ies and .ldt, any case.
bool isPhotometricFile(const std::string& path);

/// Reads an IES LM-63 (1986, 1991, 1995, 2002, 2019) or EULUMDAT (.ldt) file, by its
/// extension (.ies, .ldt, any case). Throws InputError naming the file and the line.
Photometry readPhotometry(const std::string& path);

/// The same from text already read; `name` is used in messages and its extension picks
/// the format; a TILT=<file> is looked up beside `name`.
Photometry parseIes(const std::string& text, const std::string& name);
Photometry parseLdt(const std::string& text, const std::string& name);

}  // namespace rayrad::scene
