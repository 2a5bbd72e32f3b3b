#include <app/light_group_parts.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace rayrad::app {

namespace {
std::string groupName(const std::string& g) {
    return g.empty() ? "(none)" : g;
}
double total(const radiosity::SensorValue& v) {
    return luminance(v.direct + v.indirect);
}
}  // namespace

bool hasLightGroups(const scene::SceneDesc& desc) {
    for (const auto& l : desc.lights)
        if (!l.lightGroup.empty()) return true;
    for (const auto& m : desc.materials)
        if (m.emissive && !m.lightGroup.empty()) return true;
    return false;
}

LightGroupParts solveLightGroups(const std::string& sceneFile, const PipelineOptions& base, const PipelineRun& full,
                                 const std::vector<std::string>& groups, bool keepSolutions) {
    LightGroupParts out;
    out.groups = groups;
    for (size_t g = 0; g < groups.size(); ++g) {
        PipelineOptions o;
        o.overrides = base.overrides;
        // The full solve's ΔI_max, not one derived from this group's own (dimmer) light:
        // every group's transfers are then refined to the same absolute accuracy.
        o.overrides.push_back(
            {"clusters.max_illuminance_step_lx", fmt::format("{:.17g}", full.lighting.maxIlluminanceStep)});
        o.quiet = true;
        o.lightGroup = groups[g];
        if (!base.quiet)
            fmt::print(stderr, "light group {} ({} of {}): solving\n", groupName(groups[g]), g + 1, groups.size());
        o.wantSensors = base.wantSensors;
        PipelineRun run = runPipeline(sceneFile, o);
        std::vector<radiosity::SensorValue> values;
        for (const auto& s : run.sensors) values.push_back(s.value);
        out.parts.push_back(std::move(values));
        if (keepSolutions) out.solutions.push_back({groups[g], std::move(run.lighting.solution)});
    }
    return out;
}

std::string lightGroupTable(const std::vector<SensorResult>& full, const LightGroupParts& parts) {
    std::string s = fmt::format("{:<14}", "sensor");
    for (const auto& g : parts.groups) s += fmt::format(" {:>12}", groupName(g).substr(0, 12));
    s += fmt::format(" {:>12} {:>12} {:>8}\n", "sum lx", "full lx", "diff");
    for (size_t i = 0; i < full.size(); ++i) {
        s += fmt::format("{:<14}", full[i].sensor.name);
        double sum = 0;
        for (const auto& part : parts.parts) {
            s += fmt::format(" {:>12.2f}", total(part[i]));
            sum += total(part[i]);
        }
        const double whole = total(full[i].value);
        s += fmt::format(" {:>12.2f} {:>12.2f} {:>7.3f}%\n", sum, whole, whole > 0 ? 100 * (sum - whole) / whole : 0.0);
    }
    return s;
}

double largestGroupSumDifference(const std::vector<SensorResult>& full, const LightGroupParts& parts) {
    double worst = 0;
    for (size_t i = 0; i < full.size(); ++i) {
        const double whole = total(full[i].value);
        if (whole <= 0) continue;
        double sum = 0;
        for (const auto& part : parts.parts) sum += total(part[i]);
        worst = std::max(worst, std::abs(sum - whole) / whole);
    }
    return worst;
}

std::string lightGroupCsv(const std::vector<SensorResult>& full, const LightGroupParts& parts) {
    std::string s = "sensor,group,direct_lx,indirect_lx,total_lx\n";
    for (size_t i = 0; i < full.size(); ++i)
        for (size_t g = 0; g < parts.groups.size(); ++g) {
            const auto& v = parts.parts[g][i];
            s +=
                fmt::format("{},{},{:.9g},{:.9g},{:.9g}\n", csvField(full[i].sensor.name),
                            csvField(groupName(parts.groups[g])), luminance(v.direct), luminance(v.indirect), total(v));
        }
    return s;
}

std::string lightGroupPath(const std::string& sensorCsvPath) {
    const std::filesystem::path p(sensorCsvPath);
    return (p.parent_path() / (p.stem().string() + ".groups" + p.extension().string())).string();
}

}  // namespace rayrad::app
