// The Perez all-weather sky: its luminance distribution from the sky's clearness and
// brightness, and the luminous efficacy that turns a weather file's irradiances into
// illuminances.
#pragma once

#include <scene/daylight/sky.h>

namespace rayrad::scene {

/// What the Perez models make of one hour's direct and diffuse light.
struct PerezSky {
    double clearness = 1;   ///< ε, Perez 1990 eq. 1: from 1 (overcast) to 12 (clear)
    double brightness = 0;  ///< Δ, Perez 1990 eq. 2: D m / I₀, held within the fit's 0.01 … 0.6
    int bin = 0;            ///< the clearness bin ε falls in, 0 … 7
    CieSkyParameters coefficients{};  ///< a, b, c, d, e of the luminance distribution
    double diffuseHorizontalIlluminance = 0;  ///< E_dh, lx
    double directNormalIlluminance = 0;       ///< E_n, lx
    double diffuseHorizontalIrradiance = 0;   ///< D, W/m²
    double directNormalIrradiance = 0;        ///< I, W/m²
};

/// The inputs: the sun's zenith angle, the day of the year (for the Earth–Sun distance:
/// 0 takes the mean distance) and the dew point (for the atmosphere's precipitable water,
/// W = exp(0.07 T_d − 0.075) cm, Perez 1990 eq. 3).
struct PerezConditions {
    double sunZenithRad = 0;
    int dayOfYear = 0;
    double dewPointC = 11;
};

/// From direct normal and diffuse horizontal irradiance (W/m²): ε and Δ, their bin, the
/// luminous efficacies (Perez et al. 1990, table 4, eqs. 7 and 8) and the distribution's
/// coefficients (Perez, Seals & Michalsky 1993, table 1, eqs. 6–8).
PerezSky perezFromIrradiance(double directNormal, double diffuseHorizontal, const PerezConditions& c);

/// From direct normal and diffuse horizontal illuminance (lx), as a weather file also
/// gives them: the irradiances found by iterating the efficacies (at most 20 rounds, to
/// 0.1 W/m²); the illuminances are kept as given.
PerezSky perezFromIlluminance(double directNormal, double diffuseHorizontal, const PerezConditions& c);

/// The relative air mass toward zenith angle Z (Kasten 1966), as Perez 1990 uses it.
double relativeAirMass(double zenithRad);

}  // namespace rayrad::scene
