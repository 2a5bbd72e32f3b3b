#include <app/run_report.h>

#include <app/grid_statistics.h>
#include <core/math.h>
#include <radiosity/radiosity.h>

#include <nlohmann/json.hpp>

namespace rayrad::app {

namespace {

/// Each group's name, the largest difference of the groups' sum from the full solve, and
/// per sensor each group's part: a designer scales a part to dim its group.
nlohmann::json lightGroupJson(const std::vector<SensorResult>& full, const LightGroupParts& parts) {
    using nlohmann::json;
    json j;
    j["groups"] = json::array();
    for (const auto& g : parts.groups) j["groups"].push_back(g.empty() ? json(nullptr) : json(g));
    j["largest_sum_difference_pct"] = 100 * largestGroupSumDifference(full, parts);
    j["sensors"] = json::array();
    for (size_t i = 0; i < full.size(); ++i) {
        json sensor = {{"name", full[i].sensor.name}, {"parts", json::array()}};
        for (size_t g = 0; g < parts.groups.size(); ++g) {
            const auto& v = parts.parts[g][i];
            sensor["parts"].push_back({{"direct_lx", luminance(v.direct)},
                                       {"indirect_lx", luminance(v.indirect)},
                                       {"total_lx", luminance(v.direct) + luminance(v.indirect)}});
        }
        j["sensors"].push_back(std::move(sensor));
    }
    return j;
}

}  // namespace

std::string runReportJson(const PipelineRun& run, const std::string& sceneFile, const LightGroupParts* groups) {
    using nlohmann::json;
    json j;
    j["scene"] = sceneFile;
    j["patches"] = run.mesh.patches.size();
    j["clusters"] = {{"enabled", run.lighting.clustering.enabled},
                     {"count", run.lighting.clustering.clusters.size()},
                     {"multi_patch", run.lighting.clustering.multiPatchClusters()},
                     {"voxel_size_m", run.lighting.clustering.voxelSize},
                     {"max_illuminance_step_lx", run.lighting.maxIlluminanceStep}};
    const auto& s = run.lighting.solution;
    j["solve"] = {{"seconds", s.seconds},
                  {"shots", s.shots},
                  {"converged", s.converged},
                  {"unshot_fraction", s.unshotFraction()},  // of the emitted flux
                  {"first_reflection_lm", s.initialUnshotFlux},
                  {"cluster_transfers", run.lighting.shooting.clusterTransfers},
                  {"cluster_transfers_split", run.lighting.shooting.splitTransfers},
                  {"image_cluster_transfers", run.lighting.shooting.imageTransfers},
                  {"image_cluster_transfers_carrying_light", run.lighting.shooting.imageTransfersLit},
                  {"patch_pairs", run.lighting.shooting.patchPairs},
                  {"corrections", run.lighting.shooting.corrections},
                  {"push_pulls", run.lighting.shooting.pushPulls},
                  {"channels", run.lighting.singleChannel ? 1 : 3}};
    if (run.lighting.lights) {
        auto b = energyBalanceOf(run);
        j["energy_lm"] = {{"emitted", b.emitted},
                          {"absorbed", b.absorbed},
                          {"absorbed_by_mirrors", b.mirrorAbsorbed},
                          {"absorbed_on_backs", b.backAbsorbed},
                          {"unshot", b.unshot},
                          {"left_through_openings", b.leftThroughOpenings},
                          {"passed_through_openings", b.passedThrough},
                          {"not_accounted_pct", 100 * b.relativeError()}};
    }
    j["stages"] = json::array();
    for (const auto& st : run.report.stages())
        j["stages"].push_back(
            {{"name", st.name}, {"seconds", st.seconds}, {"cpu_seconds", st.cpuSeconds}, {"peak_bytes", st.peakBytes}});
    j["total_seconds"] = run.report.totalSeconds();
    j["peak_bytes"] = peakMemoryBytes();
    j["sensors"] = json::array();
    for (const auto& r : run.sensors) {
        json e = {{"name", r.sensor.name},
                  {"direct_lx", luminance(r.value.direct)},
                  {"indirect_lx", luminance(r.value.indirect)}};
        if (r.value.indirectVertex) e["indirect_vertex_lx"] = luminance(*r.value.indirectVertex);
        if (r.sensor.refDirect) e["ref_direct_lx"] = *r.sensor.refDirect;
        if (r.sensor.refIndirect) e["ref_indirect_lx"] = *r.sensor.refIndirect;
        if (r.sensor.refTotal) e["ref_total_lx"] = *r.sensor.refTotal;
        if (!r.excluded.empty()) e["excluded"] = r.excluded;
        if (r.daylightFactor) e["daylight_factor_pct"] = *r.daylightFactor;
        j["sensors"].push_back(e);
    }
    j["grids"] = json::array();
    const auto& day = run.scene.daylight;
    for (const auto& g : gridStatistics(run.sensors, day ? day->medianExternalIlluminance : std::nullopt)) {
        json e = {{"grid", g.grid},    {"points", g.points},        {"emin_lx", g.minimum},
                  {"eavg_lx", g.mean}, {"emedian_lx", g.median},    {"emax_lx", g.maximum},
                  {"u0", g.u0()},      {"emin_emax", g.minToMax()}, {"excluded_points", g.excluded}};
        if (g.dfMean) e["daylight_factor_pct"] = {{"min", *g.dfMinimum}, {"mean", *g.dfMean}, {"median", *g.dfMedian}};
        if (g.shareAboveTarget)
            e["en17037_method1"] = {{"d_t_pct", *g.dfTarget},
                                    {"d_tm_pct", *g.dfTargetMinimum},
                                    {"share_above_d_t", *g.shareAboveTarget},
                                    {"share_above_d_tm", *g.shareAboveTargetMinimum},
                                    {"minimum_level_met", g.meetsEn17037Minimum()}};
        j["grids"].push_back(e);
    }
    if (groups) j["light_groups"] = lightGroupJson(run.sensors, *groups);
    if (!run.glare.empty()) j["observers"] = observerGlareJson(run.glare);
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) +
           "\n";  // names may come from --set or mesh files
}

}  // namespace rayrad::app
