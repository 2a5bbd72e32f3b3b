#include <radiosity/gather/sensors.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <mutex>

namespace rayrad::radiosity {

SensorValue evaluateSensor(const scene::Scene& scene, const PatchMesh& mesh, const RadiositySolution& solution,
                           const DirectLight& lights, const Visibility& vis, const Gatherer& gatherer, GatherMemo& memo,
                           const scene::Sensor& sensor) {
    SensorValue out;
    Vec3 directAt = sensor.position, gatherAt = sensor.position;
    auto where = locateOnMesh(mesh, sensor.position, sensor.normal, pointNudge(scene), &vis);
    if (where) {
        if (!solution.vertexIndirect.empty())
            out.indirectVertex = interpolateIndirect(mesh, solution, where->patch, where->u, where->v);
        // The limit from inside the sensor's own patch: the gather always (a point on a
        // mesh vertex is a singular point of its neighbours' form factors); the direct
        // light where the sensor's surface ends (an edge, a corner, the foot of a wall),
        // so its shadow rays do not start in the neighbouring surface or slip past a
        // wall standing there. Elsewhere the exact point: a light 1 mm away is exact.
        const double nudge = pointNudge(scene);
        gatherAt = nudgeInside(mesh, where->patch, sensor.position, nudge);
        if (onSurfaceBoundary(mesh, *where, 10 * nudge, &vis)) directAt = gatherAt;
    }
    out.direct = lights.illuminance(directAt, sensor.normal, vis, scene.render.sensorAreaLightSamples, nullptr);
    // The mesh's value tells the gather which far sources bring the sensor its light.
    if (!solution.indirect.empty()) {
        const double expected = out.indirectVertex ? luminance(*out.indirectVertex) : 0;  // lx; 0: not on a mesh
        out.indirect = gatherer.indirectAt(gatherAt, sensor.normal, memo, expected);
    }
    return out;
}

std::optional<std::string> slowSensorsWarning(size_t done, size_t count, double spentCpu) {
    if (done == 0 || done >= count || spentCpu < kSensorProbeSeconds) return std::nullopt;
    const double each = spentCpu / static_cast<double>(done), total = each * static_cast<double>(count);
    if (total <= kSlowSensorSeconds) return std::nullopt;
    return fmt::format(
        "/sensors: the first {} of {} sensors took {:.2g} CPU-s each; all of them will take about {:.0f} "
        "CPU-minutes (a sensor among furniture, or above a mesh coarse for it, re-gathers hundreds of points; "
        "radiosity.gather_levels=1 takes one gather a sensor, with the mesh's values beside it)",
        done, count, each, total / 60);
}

size_t sensorsPerMemo(size_t sensors) {
    return std::max<size_t>(32, (sensors + 7) / 8);
}

std::vector<SensorValue> evaluateSensors(const scene::Scene& scene, const PatchMesh& mesh,
                                         const RadiositySolution& solution, const DirectLight& lights,
                                         const Visibility& vis, const Gatherer& gatherer,
                                         const std::function<void(size_t, size_t)>& progress, size_t* gathers) {
    const size_t count = scene.sensors.size(), perRun = sensorsPerMemo(count);
    std::vector<SensorValue> values(count);
    std::atomic<size_t> gathered{0};
    std::mutex m;
    size_t done = 0;
    tbb::parallel_for(size_t(0), (count + perRun - 1) / perRun, [&](size_t run) {
        GatherMemo memo;
        for (size_t i = run * perRun; i < std::min(count, (run + 1) * perRun); ++i) {
            values[i] = evaluateSensor(scene, mesh, solution, lights, vis, gatherer, memo, scene.sensors[i]);
            std::lock_guard<std::mutex> lock(m);
            if (progress) progress(++done, count);
        }
        gathered += memo.gathers();
    });
    if (gathers) *gathers = gathered;
    return values;
}

}  // namespace rayrad::radiosity
