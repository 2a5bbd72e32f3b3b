// UGR at the scene's observers (CIE 117): every luminaire and area light the eye sees,
// its luminance toward the eye, solid angle and position index, against the background
// luminance of the indirect light at the eye.
#pragma once

#include <app/glare/fisheye_glare.h>
#include <app/glare/glare_formulas.h>
#include <scene/photometry.h>
#include <scene/observers.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

struct PipelineRun;

struct ObserverGlare {
    scene::Observer observer;
    /// The luminaires and area lights the eye sees, largest L² ω / P² first.
    std::vector<GlareSource> sources;
    /// Illuminance at the eye on the plane facing the line of sight, lx: direct from the
    /// lights (and the sky and sun, if any), and interreflected.
    double directVertical = 0, indirectVertical = 0;
    double backgroundLuminance = 0;  ///< L_b = E_ind / π, cd/m²
    std::optional<double> ugr;       ///< nothing when no source is seen, or no background
    std::string note;                ///< why there is no UGR, or ""
    /// Under a daylight (or with pictures): DGP from the sources of a fisheye rendered at the
    /// eye (kObserverFisheyePixels square, analyseFisheye's default threshold) and the
    /// luminaires it does not draw, with the gathered E_v (direct + indirect); how many.
    std::optional<double> dgp;
    size_t dgpSources = 0;
    std::optional<MarkedPicture> marked;  ///< the fisheye with its sources marked, when asked for
    /// Within the observer's limit (true when it has none or sees no source).
    bool passes() const { return !observer.ugrLimit || !ugr || *ugr <= *observer.ugrLimit; }
};

/// A luminaire's luminous area projected toward unit direction `w` given in its frame
/// (x along C0, its length; y along C90; z the nadir), m²: a rectangular opening
/// width × length facing down, a round one of diameter `width`, and the sides of its
/// height:
///   rectangle  A_p = w l |z| + l h |y| + w h |x|
///   round      A_p = π w²/4 |z| + w h √(1 − z²)
/// A flat opening seen edge-on is held to at least kMinProjectedShare of its area (its
/// luminance I / A_p would grow without bound while I need not vanish).
double projectedLuminousArea(const scene::Photometry& p, const Vec3& w);
constexpr double kMinProjectedShare = 0.087;  // cos 85°

/// The fisheye an observer's DGP is found in: this many pixels square.
constexpr int kObserverFisheyePixels = 360;

/// Every observer of a solved run (stage "glare (N observers)", and under a daylight or with
/// `pictures` a ray trace of each observer's fisheye: its DGP, and with `pictures` the
/// marked picture). Throws InputError for an observer inside a solid, and for a light the
/// eye sees that has no luminous area (a point light, a spot, a luminaire file without
/// one): its luminance is unknown.
std::vector<ObserverGlare> observerGlare(PipelineRun& run, bool pictures = false);

/// Where --glare-pictures DIR puts observer i's picture: DIR/NAME.png, NAME the observer's
/// name with anything but letters, digits, '.', '-' and '_' made '_' (and its index added
/// when another observer's name comes out the same).
std::string glarePicturePath(const std::string& dir, const std::vector<scene::Observer>& observers, size_t i);

/// The observers as an aligned text table for the terminal, each observer's sources below.
std::string observerGlareTable(const std::vector<ObserverGlare>& observers);

/// CSV: observer,x,y,z,dx,dy,dz,ugr,ugr_limit,task,check,background_cd_m2,
/// ev_direct_lx,ev_indirect_lx,sources,dgp,dgp_class (ugr empty when no source is seen;
/// dgp empty without a daylight).
std::string observerGlareCsv(const std::vector<ObserverGlare>& observers);

/// The observers for the JSON report: name, position, direction, ugr, ugr_limit, task,
/// passes, background_cd_m2, ev_direct_lx, ev_indirect_lx, each source's name,
/// luminance_cd_m2, solid_angle_sr, position_index, and under a daylight dgp, dgp_class and
/// dgp_sources.
nlohmann::json observerGlareJson(const std::vector<ObserverGlare>& observers);

/// Where `--sensors FILE.csv` puts the observers' glare: FILE.glare.csv.
std::string observerGlarePath(const std::string& sensorCsvPath);

}  // namespace rayrad::app
