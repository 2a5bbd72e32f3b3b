// The sky cut into patches for daylight coefficients: Tregenza's 145 and Reinhart's
// subdivisions of it (577, 2 305), each patch a band of altitude and a range of azimuth.
#pragma once

#include <core/math.h>

#include <array>
#include <cmath>
#include <vector>

namespace rayrad::scene {

/// Reinhart's subdivision of Tregenza's sky with multiplication factor MF (1: Tregenza's
/// 145 patches; 2: 577; 4: 2 305): 7 MF bands of altitude, each α = 90° / (7 MF + ½) high,
/// above them a cap of radius α/2 around the zenith. The bands hold MF × (30, 30, 24, 24,
/// 18, 12, 6) patches (each of Tregenza's bands cut into MF bands, each patch into MF
/// across). Patch 0 is the lowest band's patch centred on north; the index runs toward the
/// east around each band, then up; the cap is the last patch. Directions are in the sky's
/// frame: x east, y north, z up.
class SkyPatches {
  public:
    explicit SkyPatches(int mf = 1);

    int multiplicationFactor() const { return m_mf; }
    int count() const { return static_cast<int>(m_first.back()) + 1; }
    /// The patch the unit direction `local` (z ≥ 0) falls in.
    int patchOf(const Vec3& local) const;
    /// The patch's centre direction (its mid altitude and azimuth; the zenith for the cap).
    Vec3 centre(int patch) const;
    /// Its solid angle, sr: Δφ (sin a₁ − sin a₀); they add up to 2π.
    double solidAngle(int patch) const;
    /// Its altitude range and azimuth range (from north toward east), rad.
    void bounds(int patch, double& alt0, double& alt1, double& az0, double& az1) const;
    /// Interpolation over the patches' centres (each patch's luminance a tent around its
    /// centre): the weights of the patches at the unit direction `local` (z ≥ 0), linear in
    /// altitude between the two bands whose centre altitudes bracket it (the lowest band's
    /// held below its centre, the cap at the zenith) and, in each band, in azimuth between
    /// the two patches whose centres bracket it. At most four; they add up to 1, and a sky
    /// linear between the centres is reproduced.
    struct Weights {
        int count = 0;
        std::array<int, 4> patch{};
        std::array<double, 4> weight{};
    };
    Weights weights(const Vec3& local) const;
    /// The weight of `patch` at `local` (0 where its tent does not reach).
    double weight(int patch, const Vec3& local) const;
    /// ∫ weight(patch, ω) dω over the sky, sr: the solid angle of its tent (they add up to 2π).
    double tentSolidAngle(int patch) const { return m_tentSolidAngle[static_cast<size_t>(patch)]; }
    /// Directions evenly over the sky, each standing for the same solid angle (2π / count):
    /// `rings` bands even in sin(altitude), 4 × rings across.
    template <class F>
    void forEachDirection(int rings, F&& f) const {
        const int sectors = 4 * rings;
        const double dOmega = 2 * kPi / (static_cast<double>(rings) * sectors);
        for (int i = 0; i < rings; ++i) {
            const double s = (i + 0.5) / rings, c = std::sqrt(1 - s * s);
            for (int j = 0; j < sectors; ++j) {
                const double az = 2 * kPi * (j + 0.5) / sectors;
                f(Vec3(std::sin(az) * c, std::cos(az) * c, s), dOmega);
            }
        }
    }

  private:
    /// Adds band `band`'s two patches around azimuth `az` (rad from north) with weight w.
    void addBand(size_t band, double az, double w, Weights& out) const;

    int m_mf = 1;
    double m_band = 0;                 ///< α, rad
    std::vector<int> m_perBand;        ///< patches in each band
    std::vector<int> m_first;          ///< index of each band's first patch; the last entry the cap
    std::vector<double> m_tentSolidAngle;
};

}  // namespace rayrad::scene
