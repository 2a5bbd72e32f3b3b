#include <scene/daylight/sky_patches.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rayrad::scene {

namespace {
constexpr int kTregenzaBands[] = {30, 30, 24, 24, 18, 12, 6};  // patches per band, from the horizon up
}

SkyPatches::SkyPatches(int mf) : m_mf(mf) {
    if (mf < 1) throw std::invalid_argument("sky patches: the multiplication factor must be at least 1");
    m_band = (kPi / 2) / (7 * mf + 0.5);
    int first = 0;
    for (int t = 0; t < 7; ++t)
        for (int k = 0; k < mf; ++k) {
            m_perBand.push_back(kTregenzaBands[t] * mf);
            m_first.push_back(first);
            first += kTregenzaBands[t] * mf;
        }
    m_first.push_back(first);  // the cap
    m_tentSolidAngle.assign(static_cast<size_t>(count()), 0.0);
    forEachDirection(96 * mf, [&](const Vec3& w, double dOmega) {
        const Weights t = weights(w);
        for (int k = 0; k < t.count; ++k) m_tentSolidAngle[static_cast<size_t>(t.patch[k])] += t.weight[k] * dOmega;
    });
}

int SkyPatches::patchOf(const Vec3& local) const {
    const double altitude = std::asin(std::clamp(local.z, -1.0, 1.0));
    const int band = static_cast<int>(std::floor(std::max(altitude, 0.0) / m_band));
    if (band >= static_cast<int>(m_perBand.size())) return m_first.back();
    const int n = m_perBand[static_cast<size_t>(band)];
    // Azimuth from north toward east; patch 0 of a band is centred on north.
    double az = std::atan2(local.x, local.y) + kPi / n;
    if (az < 0) az += 2 * kPi;
    const int k = std::min(n - 1, static_cast<int>(az / (2 * kPi / n)));
    return m_first[static_cast<size_t>(band)] + k;
}

void SkyPatches::addBand(size_t band, double az, double w, Weights& out) const {
    if (w <= 0) return;
    if (band == m_perBand.size()) {  // the cap: one patch
        out.patch[out.count] = m_first.back(), out.weight[out.count++] = w;
        return;
    }
    const int n = m_perBand[band];
    const double u = az / (2 * kPi / n);  // patch k's centre at u = k
    const double k0 = std::floor(u), f = u - k0;
    const int a = ((static_cast<int>(k0) % n) + n) % n, b = (a + 1) % n;
    out.patch[out.count] = m_first[band] + a, out.weight[out.count++] = w * (1 - f);
    out.patch[out.count] = m_first[band] + b, out.weight[out.count++] = w * f;
}

SkyPatches::Weights SkyPatches::weights(const Vec3& local) const {
    Weights out;
    const double altitude = std::asin(std::clamp(local.z, -1.0, 1.0));
    double az = std::atan2(local.x, local.y);
    if (az < 0) az += 2 * kPi;
    const size_t bands = m_perBand.size();
    // Band b's node at its centre altitude (b + ½) α (the lowest band's held below it), the
    // cap's at the zenith.
    const double u = altitude / m_band - 0.5;
    if (u <= 0) {
        addBand(0, az, 1.0, out);
    } else if (u >= bands - 1) {
        const double top = (bands - 0.5) * m_band, t = (altitude - top) / (kPi / 2 - top);
        addBand(bands - 1, az, 1 - t, out);
        addBand(bands, az, t, out);
    } else {
        const size_t b = static_cast<size_t>(u);
        const double t = u - b;
        addBand(b, az, 1 - t, out);
        addBand(b + 1, az, t, out);
    }
    return out;
}

double SkyPatches::weight(int patch, const Vec3& local) const {
    const Weights w = weights(local);
    double sum = 0;
    for (int k = 0; k < w.count; ++k)
        if (w.patch[k] == patch) sum += w.weight[k];
    return sum;
}

void SkyPatches::bounds(int patch, double& alt0, double& alt1, double& az0, double& az1) const {
    const auto it = std::upper_bound(m_first.begin(), m_first.end(), patch);
    const size_t band = static_cast<size_t>(it - m_first.begin()) - 1;
    if (band == m_perBand.size()) {  // the cap
        alt0 = band * m_band, alt1 = kPi / 2, az0 = 0, az1 = 2 * kPi;
        return;
    }
    const int n = m_perBand[band], k = patch - m_first[band];
    const double width = 2 * kPi / n;
    alt0 = band * m_band, alt1 = (band + 1) * m_band;
    az0 = (k - 0.5) * width, az1 = (k + 0.5) * width;
}

Vec3 SkyPatches::centre(int patch) const {
    double a0, a1, z0, z1;
    bounds(patch, a0, a1, z0, z1);
    if (patch == m_first.back()) return {0, 0, 1};
    const double a = 0.5 * (a0 + a1), z = 0.5 * (z0 + z1);
    return {std::sin(z) * std::cos(a), std::cos(z) * std::cos(a), std::sin(a)};
}

double SkyPatches::solidAngle(int patch) const {
    double a0, a1, z0, z1;
    bounds(patch, a0, a1, z0, z1);
    return (z1 - z0) * (std::sin(a1) - std::sin(a0));
}

}  // namespace rayrad::scene
