#include <app/annual/annual_command.h>

#include <app/annual/hour_images.h>

#include <app/annual/annual_skies.h>
#include <app/annual/daylight_coefficients.h>
#include <app/annual/daylight_dimming.h>
#include <app/annual/hour_images.h>
#include <app/run_outputs.h>
#include <app/sensor_table.h>
#include <core/input_error.h>
#include <core/output_file.h>
#include <core/result_error.h>
#include <core/stage_report.h>
#include <scene/light_groups.h>
#include <tonemap/false_colour.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <map>

namespace rayrad::app {

Occupancy parseOccupancy(const std::string& text, const std::string& saving) {
    Occupancy o;
    const auto dash = text.find('-');
    char* end = nullptr;
    bool ok = dash != std::string::npos && dash > 0;
    if (ok) {
        const std::string a = text.substr(0, dash), b = text.substr(dash + 1);
        o.start = std::strtod(a.c_str(), &end);
        ok = *end == '\0';
        o.end = std::strtod(b.c_str(), &end);
        ok = ok && *end == '\0' && !b.empty();
    }
    if (!ok || !(o.start >= 0 && o.end <= 24 && o.start < o.end))
        throw InputError(placeMessage("--occupancy", "",
                                      fmt::format("expected START-END in hours of the clock, 0 ≤ START < END ≤ 24 "
                                                  "(e.g. 8-18), got \"{}\"",
                                                  text)));
    if (saving == "none") o.saving = DaylightSaving::None;
    else if (saving == "us") o.saving = DaylightSaving::UnitedStates;
    else if (saving == "eu") o.saving = DaylightSaving::Europe;
    else
        throw InputError(placeMessage("--daylight-saving", "",
                                      fmt::format("expected none, us or eu, got \"{}\"", saving)));
    return o;
}

int patchMultiplicationFactor(int patches) {
    for (int mf : {1, 2, 4})
        if (scene::SkyPatches(mf).count() == patches) return mf;
    throw InputError(placeMessage("--sky-patches", "",
                                  fmt::format("expected 145, 577 or 2305 sky patches, got {}", patches)));
}

std::optional<std::string> weatherPlaceWarning(const scene::WeatherFile& weather, const scene::Daylight& daylight) {
    if (!daylight.site) return std::nullopt;
    const double dLat = std::abs(weather.latitudeDeg - daylight.site->latitudeDeg);
    double dLon = std::abs(weather.longitudeDeg - daylight.site->longitudeDeg);
    dLon = std::min(dLon, 360 - dLon);
    if (dLat <= 1 && dLon <= 1) return std::nullopt;
    return fmt::format("the weather file is for {} ({:.2f}°, {:.2f}°) but the scene's sun is placed at ({:.2f}°, "
                       "{:.2f}°): the study uses the weather file's place and time zone",
                       weather.city.empty() ? std::string("its place") : weather.city, weather.latitudeDeg,
                       weather.longitudeDeg, daylight.site->latitudeDeg, daylight.site->longitudeDeg);
}

std::string annualMetricsCsv(const std::vector<scene::Sensor>& sensors, const AnnualStudy& study,
                             const std::vector<std::string>& excluded,
                             const std::vector<std::optional<double>>& lampShares) {
    std::string s = "sensor,grid,da_pct,cda_pct,udi_below_pct,udi_useful_pct,udi_above_pct,sun_hours,"
                    "en17037_target_pct,en17037_minimum_pct,excluded";
    s += lampShares.empty() ? "\n" : ",lamp_energy_pct\n";
    for (size_t i = 0; i < study.points; ++i) {
        const PointYear& p = study.pointYears[i];
        s += fmt::format("{},{},{:.2f},{:.2f},{:.2f},{:.2f},{:.2f},{},{:.2f},{:.2f},{}", csvField(sensors[i].name),
                         csvField(sensors[i].grid), 100 * p.da, 100 * p.cda, 100 * p.udiBelow, 100 * p.udiUseful,
                         100 * p.udiAbove, p.sunHours, 100 * p.enTarget, 100 * p.enMinimum,
                         csvField(i < excluded.size() ? excluded[i] : std::string()));
        if (!lampShares.empty()) s += lampShares[i] ? fmt::format(",{:.2f}", 100 * *lampShares[i]) : std::string(",");
        s += "\n";
    }
    return s;
}

std::string annualHourlyFile(const AnnualStudy& study) {
    std::string s = fmt::format(
        "rayrad hourly illuminance 1 points={} hours={} layout=point-major float32-le total-then-sun\n", study.points,
        study.hours);
    const size_t header = s.size(), n = study.total.size() * sizeof(float);
    s.resize(header + 2 * n);
    std::memcpy(&s[header], study.total.data(), n);
    std::memcpy(&s[header + n], study.sun.data(), n);
    return s;
}

std::string annualGridTable(const AnnualStudy& study, const AnnualThresholds& t) {
    std::string s = fmt::format("{:<16} {:>6} {:>9} {:>9} {:>8} {:>9} {:>22}\n", "grid", "points",
                                fmt::format("sDA{:.0f}", t.daLux), fmt::format("ASE{:.0f}", t.aseLux), "mean DA",
                                "UDI 100-3k", "EN 17037 300/100 lx");
    for (const GridYear& g : study.grids)
        s += fmt::format("{:<16} {:>6} {:>8.1f}% {:>8.1f}% {:>7.1f}% {:>8.1f}% {:>8.0f}% {:>4.0f}% {}\n", g.grid.substr(0, 16),
                         g.points, 100 * g.sda, 100 * g.ase, 100 * g.meanDa, 100 * g.meanUdiUseful,
                         100 * g.enTargetShare, 100 * g.enMinimumShare, g.meetsEn17037Minimum() ? "met" : "not met");
    return s;
}

namespace {

/// Each grid's DA, ASE sun hours and useful UDI as false-colour plans, stacked.
tonemap::Picture annualPlans(const std::vector<scene::Sensor>& sensors, const AnnualStudy& study,
                             const std::vector<std::string>& excluded, const AnnualThresholds& t) {
    std::vector<tonemap::Picture> pictures;
    for (const GridYear& g : study.grids) {
        int nu = 0, nv = 0;
        for (const auto& s : sensors)
            if (s.grid == g.grid) nu = std::max(nu, s.gridU + 1), nv = std::max(nv, s.gridV + 1);
        if (nu <= 0 || nv <= 0) continue;
        auto plan = [&](auto value, const std::string& unit, double maximum, const std::string& title) {
            tonemap::ScalarField field;
            field.width = nu, field.height = nv;
            field.values.assign(static_cast<size_t>(nu) * nv, std::numeric_limits<double>::quiet_NaN());
            for (size_t i = 0; i < sensors.size(); ++i)
                if (sensors[i].grid == g.grid && sensors[i].gridU >= 0 && (i >= excluded.size() || excluded[i].empty()))
                    field.values[static_cast<size_t>(sensors[i].gridV) * nu + sensors[i].gridU] =
                        value(study.pointYears[i]);
            tonemap::FalseColourOptions o;
            o.unit = unit;
            o.maximum = maximum;
            o.pixelsPerValue = std::clamp(480 / std::max(nu, nv), 4, 64);
            o.title = title;
            pictures.push_back(tonemap::renderFalseColour(field, o));
        };
        plan([](const PointYear& p) { return 100 * p.da; }, "%", 100,
             fmt::format("{}: daylight autonomy DA{:.0f} (% of occupied hours); sDA{:.0f}/{:.0f}% = {:.1f} %", g.grid,
                         t.daLux, t.daLux, 100 * t.daShare, 100 * g.sda));
        plan([](const PointYear& p) { return static_cast<double>(p.sunHours); }, "h", 0,
             fmt::format("{}: occupied hours of direct sun >= {:.0f} lx; ASE{:.0f},{:.0f}h = {:.1f} %", g.grid,
                         t.aseLux, t.aseLux, t.aseHours, 100 * g.ase));
        plan([](const PointYear& p) { return 100 * p.udiUseful; }, "%", 100,
             fmt::format("{}: useful daylight illuminance {:.0f}-{:.0f} lx (% of occupied hours)", g.grid, t.udiLow,
                         t.udiHigh));
    }
    return pictures.empty() ? tonemap::Picture{} : tonemap::stackPictures(pictures);
}

std::string annualReportJson(const std::string& sceneFile, const scene::WeatherFile& weather, int patches,
                             const Occupancy& occupancy, const DaylightCoefficients& dc, const AnnualStudy& study,
                             const std::vector<scene::Sensor>& sensors, const std::vector<std::string>& excluded,
                             double dimming, const std::vector<std::optional<double>>& lampShares,
                             const std::vector<GroupDimming>& dimmedGroups) {
    nlohmann::json j;
    j["scene"] = sceneFile;
    j["weather"] = {{"file", weather.path},      {"place", weather.city},
                    {"country", weather.country}, {"latitude_deg", weather.latitudeDeg},
                    {"longitude_deg", weather.longitudeDeg}, {"time_zone_h", weather.timeZoneHours}};
    j["sky_patches"] = patches;
    j["occupancy"] = {{"start_h", occupancy.start}, {"end_h", occupancy.end}, {"hours", study.occupiedHours}};
    j["hours_with_daylight"] = study.litHours;
    if (dimming > 0) j["dimming_target_lx"] = dimming;
    for (const GroupDimming& g : dimmedGroups)
        j["dimming_groups"].push_back({{"group", g.group},
                                       {"control", sensors[g.control].name},
                                       {"control_lamp_lx", g.controlIlluminance},
                                       {"lamp_energy_share", g.energyShare}});
    j["en17037_hours"] = study.en17037HourCount;
    j["coefficients"] = {{"channels", dc.channels()},
                         {"solved_channels", dc.solvedChannels},
                         {"solved_suns", dc.solvedSuns},
                         {"cpu_s", dc.solveCpuSeconds},
                         {"wall_s", dc.solveWallSeconds}};
    j["year"] = {{"cpu_s", study.cpuSeconds}, {"wall_s", study.wallSeconds}};
    j["peak_memory_bytes"] = peakMemoryBytes();
    for (const GridYear& g : study.grids)
        j["grids"].push_back({{"grid", g.grid},
                              {"points", g.points},
                              {"sda", g.sda},
                              {"ase", g.ase},
                              {"mean_da", g.meanDa},
                              {"mean_udi_useful", g.meanUdiUseful},
                              {"en17037_target_share", g.enTargetShare},
                              {"en17037_minimum_share", g.enMinimumShare},
                              {"en17037_minimum_met", g.meetsEn17037Minimum()}});
    for (size_t i = 0; i < study.points; ++i) {
        const PointYear& p = study.pointYears[i];
        nlohmann::json e = {{"name", sensors[i].name}, {"da", p.da}, {"cda", p.cda}, {"udi_below", p.udiBelow},
                            {"udi_useful", p.udiUseful}, {"udi_above", p.udiAbove}, {"sun_hours", p.sunHours},
                            {"en17037_target", p.enTarget}, {"en17037_minimum", p.enMinimum}};
        if (!sensors[i].grid.empty()) e["grid"] = sensors[i].grid;
        if (i < excluded.size() && !excluded[i].empty()) e["excluded"] = excluded[i];
        if (i < lampShares.size() && lampShares[i]) e["lamp_energy_share"] = *lampShares[i];
        j["sensors"].push_back(std::move(e));
    }
    return j.dump(2) + "\n";
}

/// Daylight-linked dimming: the lamps' energy share per single sensor and per grid (its
/// points' mean).
void printDimming(const std::vector<scene::Sensor>& sensors, const std::vector<std::optional<double>>& shares,
                  double target) {
    std::vector<std::string> order;
    std::map<std::string, std::pair<double, int>> grids;
    fmt::print("daylight-linked dimming to {:g} lx, the lamps' energy over the occupied hours (100 %: always full):\n",
               target);
    for (size_t i = 0; i < sensors.size(); ++i) {
        if (!shares[i]) continue;
        if (sensors[i].grid.empty()) {
            fmt::print("  {:<16} {:6.1f} %\n", sensors[i].name, 100 * *shares[i]);
            continue;
        }
        auto [it, added] = grids.try_emplace(sensors[i].grid, 0.0, 0);
        if (added) order.push_back(sensors[i].grid);
        it->second.first += *shares[i], ++it->second.second;
    }
    for (const auto& g : order)
        fmt::print("  {:<16} {:6.1f} % (mean of {} points)\n", g, 100 * grids[g].first / grids[g].second,
                   grids[g].second);
}

/// Each light group dimmed by its control point.
void printGroupDimming(const std::vector<scene::Sensor>& sensors, const std::vector<GroupDimming>& groups,
                       double target) {
    fmt::print("light groups dimmed to {:g} lx at their control points, their energy over the occupied hours:\n",
               target);
    for (const GroupDimming& g : groups)
        fmt::print("  {:<16} {:6.1f} %  (control: {}, {:.0f} lx from the group at full output)\n",
                   g.group.empty() ? "(no group)" : g.group, 100 * g.energyShare, sensors[g.control].name,
                   g.controlIlluminance);
}

/// One hour at the single sensors (not the grids' points), by part.
void printHour(const PipelineRun& run, const DaylightCoefficients& dc, const SunLight& sun,
               const std::vector<SkyHour>& skies, size_t h) {
    const SkyHour& hour = skies[h];
    const double k = hour.sunNormal > 0 ? sun.sunScale(hour.toSun, hour.sunWeights) : 0.0;
    fmt::print("hour {} ({:02d}-{:02d}, {:.1f} h standard time): sun altitude {:.2f}°, azimuth {:.2f}°, E_n {:.0f} lx, "
               "E_dh {:.0f} lx; the sun's tents scaled by {:.3f}\n",
               h, hour.month, hour.day, hour.clockHour, hour.sunAltitudeDeg, hour.sunAzimuthDeg, hour.sunNormal,
               hour.diffuseHorizontal, k);
    fmt::print("{:<14} {:>11} {:>11} {:>11} {:>11} {:>11}\n", "sensor", "sky dir lx", "sky ind lx", "sun ind lx",
               "sun dir lx", "total lx");
    for (size_t i = 0; i < run.scene.sensors.size(); ++i) {
        const scene::Sensor& s = run.scene.sensors[i];
        if (!s.grid.empty()) continue;
        const double direct = hour.sunNormal > 0 ? sun.directAt(s.position, s.normal, hour.toSun) : 0.0;
        const HourParts p = hourParts(dc, i, hour, direct, k);
        fmt::print("{:<14} {:>11.1f} {:>11.1f} {:>11.1f} {:>11.1f} {:>11.1f}\n", s.name.substr(0, 14), p.skyDirect,
                   p.skyIndirect, p.sunIndirect, p.sunDirect, p.total());
    }
}

/// The outputs of the study (checked and added to `files`), --image's included, for the
/// "wrote" lines; `images` gets the hours to render. Before any work.
std::vector<std::string> addAnnualOutputs(const AnnualArgs& args, const scene::SceneDesc& desc, OutputFiles& files,
                                          std::vector<HourImage>& images) {
    if (!args.plan.empty()) {
        tonemap::checkImageFormat(args.plan);
        if (tonemap::isHdrFormat(args.plan))
            throw OutputError(placeMessage(args.plan, "", "a false-colour plan is a display image: use .png or .jpg"));
    }
    std::vector<std::string> outputs{args.metrics, args.hourly, args.plan, args.report};
    addOutputs(files, outputs);
    for (const auto& text : args.images) addHourImage(text, images, files);
    for (const auto& image : images) outputs.insert(outputs.end(), image.paths.begin(), image.paths.end());
    if (!images.empty() && !desc.camera)
        throw InputError(placeMessage(desc.file, "", "--image: the scene has no camera to render"));
    return outputs;
}

/// An InputError when the occupancy takes no hour of the weather file's year.
void checkSchedule(const scene::WeatherFile& weather, const Occupancy& occupancy, int year) {
    if (std::none_of(weather.hours.begin(), weather.hours.end(), [&](const scene::WeatherHour& h) {
            return isOccupied(year, h.month, h.day, h.hour - 0.5, occupancy);
        }))
        throw InputError(placeMessage("--occupancy", "",
                                      fmt::format("the schedule {}–{} h takes no hour of the year (the weather file's "
                                                  "hours are taken at their middles, 0:30, 1:30 …)",
                                                  occupancy.start, occupancy.end)));
}

/// --dimming: the lamps' light at every sensor at full output into `lamps` and, when they
/// name light groups, each group's with its control point (one solve each).
std::vector<GroupDimming> solveLampsForDimming(PipelineRun& run, const AnnualArgs& args, std::vector<double>& lamps) {
    if (!args.dimmingControls.empty() && !(args.dimming > 0))
        throw InputError(placeMessage("", "--dimming-control", "needs --dimming LX, the target"));
    if (!(args.dimming > 0)) return {};
    run.report.begin("lamps (for --dimming)");
    lamps = lampIlluminance(run);
    const std::vector<std::string> groups = scene::lightGroups(run.scene);
    if (groups.empty() && !args.dimmingControls.empty())
        throw InputError(
            placeMessage(run.scene.file, "", "--dimming-control: the scene's lamps name no light groups"));
    if (groups.empty()) return {};
    run.report.begin(fmt::format("light groups (for --dimming, {} solves)", groups.size()));
    std::vector<std::vector<double>> groupLamps;
    for (const auto& g : groups) groupLamps.push_back(lampIlluminance(run, g));
    return dimmingControls(run.scene.sensors, groups, groupLamps, args.dimmingControls);
}

/// The hour of "MM-DDTHH" for --image, which must have daylight to render.
size_t litYearHour(const std::string& text, const std::vector<SkyHour>& skies) {
    const size_t hour = parseYearHour(text, skies, "--image");
    if (!skies[hour].lit)
        throw InputError(placeMessage(
            "--image", "", fmt::format("the weather file's hour {} has no daylight: nothing to render", text)));
    return hour;
}

/// A broken result is no result: non-finite values, or no daylight anywhere all year.
void checkStudy(const AnnualStudy& study, const std::string& sceneFile) {
    if (std::any_of(study.total.begin(), study.total.end(), [](float v) { return !std::isfinite(v); }))
        throw ResultError("the hourly illuminance holds non-finite values. Nothing was written");
    if (std::all_of(study.total.begin(), study.total.end(), [](float v) { return v == 0; }))
        throw ResultError(placeMessage(sceneFile, "",
                                       "no sensor receives any daylight in the whole year: does any opening face the "
                                       "sky? Nothing was written"));
}

}  // namespace

int runAnnual(const AnnualArgs& args) {
    const CommonArgs& a = args.common;
    const Occupancy occupancy = parseOccupancy(args.occupancy, args.daylightSaving);
    const int mf = patchMultiplicationFactor(args.skyPatches);
    PipelineOptions o;
    for (const auto& s : a.sets) o.overrides.push_back(scene::parseOverride(s));
    o.quiet = a.quiet;
    o.wantSensors = true;
    // Read and check the scene, the weather file and every output before any work.
    const auto desc = scene::loadScene(a.scene, o.overrides);
    OutputFiles files = filesOf(desc);
    files.addInput(args.weather);
    std::vector<HourImage> images;
    const std::vector<std::string> outputs = addAnnualOutputs(args, desc, files, images);
    const scene::WeatherFile weather = scene::readWeatherFile(args.weather);
    const int year = weather.hours.size() == 8784 ? 2020 : 2021;  // the weekdays of summer time
    checkSchedule(weather, occupancy, year);

    if (!desc.daylight)
        throw InputError(placeMessage(a.scene, "", "an annual study needs the scene's \"daylight\" (its axes, ground "
                                                   "and openings); the weather file gives the sky and the sun"));
    std::vector<std::string> excluded;
    PipelineRun run = preparePipeline(a.scene, desc, o, &excluded);
    if (run.scene.sensors.empty())
        throw InputError(placeMessage(a.scene, "", "an annual study needs sensors or grids to report at"));
    if (auto w = weatherPlaceWarning(weather, *run.scene.daylight)) fmt::print(stderr, "warning: {}: {}\n", a.scene, *w);
    if (!args.plan.empty() &&
        std::none_of(run.scene.sensors.begin(), run.scene.sensors.end(), [](const auto& s) { return !s.grid.empty(); }))
        throw InputError(placeMessage(a.scene, "", "--plan: the scene has no sensor grid or work plane"));

    std::vector<double> lamps;  // lx at full output, for --dimming
    std::vector<GroupDimming> dimmedGroups = solveLampsForDimming(run, args, lamps);
    run.report.begin(fmt::format("annual skies ({} hours)", weather.hours.size()));
    const auto patches = std::make_shared<const scene::SkyPatches>(mf);
    const auto fine = std::make_shared<const scene::SkyPatches>(kDirectSkyMultiplication);
    const auto skies = annualSkies(weather, *run.scene.daylight, *patches, *fine);
    std::vector<size_t> printedHours;
    for (const auto& hour : args.hours) printedHours.push_back(parseYearHour(hour, skies));
    for (auto& image : images) image.hour = litYearHour(image.hourText, skies);
    const std::vector<char> suns = sunNodes(skies, *patches);
    const SunLight sun(run, *patches);
    HourSolutions hourSolutions(images, skies, sun, patches->count(), run.mesh.patches.size());
    run.report.begin(fmt::format("daylight coefficients ({} sky patches + ground, {} suns)", args.skyPatches,
                                 std::count(suns.begin(), suns.end(), 1)));
    const DaylightCoefficients dc = solveDaylightCoefficients(
        run, patches, fine, suns, a.quiet,
        images.empty() ? ChannelSolutionHook{} : [&](int c, int j, const radiosity::RadiositySolution& s) {
            hourSolutions.add(c, j, s);
        });
    run.report.begin(fmt::format("annual illuminance ({} sensors)", run.scene.sensors.size()));
    const AnnualThresholds thresholds;
    const AnnualStudy study = runAnnualStudy(run, dc, sun, skies, occupancy, thresholds, excluded, year);
    run.report.end();

    checkStudy(study, a.scene);

    const std::vector<std::optional<double>> lampShares =
        args.dimming > 0 ? dimmingShares(study, lamps, args.dimming) : std::vector<std::optional<double>>{};
    dimGroups(study, args.dimming, dimmedGroups);

    fmt::print("{}, {} ({:.2f}°, {:.2f}°): {} hours with daylight, {} occupied ({:g}–{:g} h), {} EN 17037 hours\n",
               weather.city, weather.country, weather.latitudeDeg, weather.longitudeDeg, study.litHours,
               study.occupiedHours, occupancy.start, occupancy.end, study.en17037HourCount);
    if (!study.grids.empty()) fmt::print("{}", annualGridTable(study, thresholds));
    if (args.dimming > 0) printDimming(run.scene.sensors, lampShares, args.dimming);
    if (!dimmedGroups.empty()) printGroupDimming(run.scene.sensors, dimmedGroups, args.dimming);
    fmt::print("coefficients: {} sky channels ({} solved) and {} suns in {:.1f} CPU-s ({:.1f} s wall); the year: {:.1f} CPU-s ({:.1f} s "
               "wall); peak memory {:.0f} MiB\n",
               dc.channels(), dc.solvedChannels, dc.solvedSuns, dc.solveCpuSeconds, dc.solveWallSeconds, study.cpuSeconds,
               study.wallSeconds, peakMemoryBytes() / 1048576.0);

    for (size_t h : printedHours) printHour(run, dc, sun, skies, h);
    for (size_t k = 0; k < images.size(); ++k)
        renderHourImage(run, weather, skies[images[k].hour], images[k], hourSolutions.solution(k), files);

    if (!args.metrics.empty())
        files.set(args.metrics, annualMetricsCsv(run.scene.sensors, study, excluded, lampShares));
    if (!args.hourly.empty()) files.set(args.hourly, annualHourlyFile(study));
    if (!args.plan.empty()) {
        const tonemap::Picture p = annualPlans(run.scene.sensors, study, excluded, thresholds);
        files.set(args.plan, tonemap::encodeDisplayImage(args.plan, p.width, p.height, p.rgb));
    }
    if (!args.report.empty())
        files.set(args.report, annualReportJson(a.scene, weather, args.skyPatches, occupancy, dc, study,
                                                run.scene.sensors, excluded, args.dimming, lampShares,
                                                dimmedGroups));
    files.commit();
    reportWritten(outputs);
    std::cerr << stagesSummary(run) << run.report.toString();
    return 0;
}

}  // namespace rayrad::app
