#include <app/annual/sky_direct.h>

#include <app/annual/opening_samples.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace rayrad::app {

DirectSkyCoefficients directSkyCoefficients(const PipelineRun& run, std::shared_ptr<const scene::SkyPatches> fine) {
    DirectSkyCoefficients out;
    out.patches = std::move(fine);
    const scene::Scene& sc = run.scene;
    const scene::Daylight& d = *sc.daylight;
    const auto openings = openingSamples(sc, 32);
    const auto glazings = openingGlazings(sc);
    const double far = 4 * std::max(sc.diagonal(), 1.0);
    const uint32_t ground = static_cast<uint32_t>(out.patches->count());
    out.terms.resize(sc.sensors.size());
    tbb::parallel_for(size_t(0), sc.sensors.size(), [&](size_t i) {
        const Vec3 x = sc.sensors[i].position, n = sc.sensors[i].normal;
        std::unordered_map<uint32_t, double> sum;
        for (const OpeningSamples& o : openings)
            for (size_t k = 0; k < o.points.size(); ++k) {
                const Vec3 dy = o.points[k] - x;
                const double r2 = glm::dot(dy, dy);
                if (!(r2 > 0)) continue;
                const Vec3 w = dy / std::sqrt(r2);
                const double cx = glm::dot(n, w), cy = glm::dot(w, o.out);
                if (cx <= 0 || cy <= 0) continue;
                const double tau = glazings->openingTransmittance(x, w, far);
                if (!(tau > 0) || !run.embree->visibleFromSurface(x, n, x + far * w)) continue;
                const double e = tau * cx * cy * o.pointArea[k] / r2;  // lx per cd/m²
                const Vec3 local = d.toLocal(w);
                if (local.z < 0) {
                    sum[ground] += e;
                    continue;
                }
                const auto t = out.patches->weights(local);
                for (int j = 0; j < t.count; ++j) sum[static_cast<uint32_t>(t.patch[j])] += e * t.weight[j];
            }
        auto& terms = out.terms[i];
        for (const auto& [tent, e] : sum)
            if (e > 0) terms.emplace_back(tent, static_cast<float>(e));
        std::sort(terms.begin(), terms.end());
    });
    return out;
}

}  // namespace rayrad::app
