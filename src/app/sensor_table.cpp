#include <app/sensor_table.h>

#include <fmt/format.h>

#include <algorithm>

#include <cmath>

#include <optional>

namespace rayrad::app {

namespace {

bool anyReference(const std::vector<SensorResult>& results) {
    for (const auto& r : results)
        if (r.sensor.refDirect || r.sensor.refIndirect || r.sensor.refTotal) return true;
    return false;
}

std::optional<double> errorPct(double value, const std::optional<double>& ref) {
    if (!ref || *ref == 0) return std::nullopt;
    return 100.0 * (value - *ref) / *ref;
}

/// A table cell in lx: two decimals, or 4 significant digits in exponent form when that
/// would not fit the column (beyond 10⁸ lx).
std::string lux(double v) {
    return std::abs(v) < 1e8 ? fmt::format("{:.2f}", v) : fmt::format("{:.4g}", v);
}

std::string cell(const std::optional<double>& v, const char* format = "{:.9g}") {
    return v ? fmt::format(fmt::runtime(format), *v) : std::string();
}

struct Row {
    double direct, indirect, total;
    std::optional<double> vertex;
};

Row rowOf(const SensorResult& r) {
    Row row;
    row.direct = luminance(r.value.direct);
    row.indirect = luminance(r.value.indirect);
    row.total = row.direct + row.indirect;
    if (r.value.indirectVertex) row.vertex = luminance(*r.value.indirectVertex);
    return row;
}

}  // namespace

bool anyDaylightFactor(const std::vector<SensorResult>& results) {
    return std::any_of(results.begin(), results.end(), [](const SensorResult& r) { return r.daylightFactor; });
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string q;
    for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return "\"" + q + "\"";
}

std::string sensorCsv(const std::vector<SensorResult>& results) {
    bool refs = anyReference(results);
    std::string s = "sensor,x,y,z,nx,ny,nz,direct_lx,indirect_lx,total_lx";
    if (refs) s += ",ref_direct_lx,ref_indirect_lx,ref_total_lx,err_direct_pct,err_indirect_pct,err_total_pct";
    s += ",indirect_vertex_lx";
    if (refs) s += ",err_indirect_vertex_pct";
    // Points that are no measurement (inside a solid), marked when there are any.
    const bool marks =
        std::any_of(results.begin(), results.end(), [](const SensorResult& r) { return !r.excluded.empty(); });
    if (marks) s += ",excluded";
    const bool factors = anyDaylightFactor(results);
    if (factors) s += ",daylight_factor_pct";
    s += "\n";
    for (const auto& r : results) {
        Row row = rowOf(r);
        const auto& p = r.sensor.position;
        const auto& n = r.sensor.normal;
        const std::string name = csvField(r.sensor.name);
        s += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}", name, p.x, p.y, p.z, n.x,
                         n.y, n.z, row.direct, row.indirect, row.total);
        if (refs)
            s += fmt::format(",{},{},{},{},{},{}", cell(r.sensor.refDirect), cell(r.sensor.refIndirect),
                             cell(r.sensor.refTotal), cell(errorPct(row.direct, r.sensor.refDirect), "{:.6f}"),
                             cell(errorPct(row.indirect, r.sensor.refIndirect), "{:.6f}"),
                             cell(errorPct(row.total, r.sensor.refTotal), "{:.6f}"));
        s += "," + cell(row.vertex);
        if (refs) s += "," + cell(row.vertex ? errorPct(*row.vertex, r.sensor.refIndirect) : std::nullopt, "{:.6f}");
        if (marks) s += "," + r.excluded;
        if (factors) s += "," + cell(r.daylightFactor, "{:.6f}");
        s += "\n";
    }
    return s;
}

std::string sensorTable(const std::vector<SensorResult>& results) {
    bool refs = anyReference(results);
    auto pct = [](const std::optional<double>& e) { return e ? fmt::format("{:+.2f}%", *e) : std::string("-"); };
    std::string s = fmt::format("{:<14} {:>11} {:>11} {:>11} {:>14}", "sensor", "direct lx", "indirect lx", "total lx",
                                "vertex ind lx");
    if (refs) s += fmt::format("  {:>9} {:>9} {:>9} {:>9}", "err dir", "err ind", "err tot", "err vtx");
    const bool factors = anyDaylightFactor(results);
    if (factors) s += fmt::format("  {:>7}", "DF %");
    s += "\n";
    for (const auto& r : results) {
        Row row = rowOf(r);
        s += fmt::format("{:<14} {:>11} {:>11} {:>11} {:>14}", r.sensor.name, lux(row.direct), lux(row.indirect),
                         lux(row.total), row.vertex ? lux(*row.vertex) : std::string("-"));
        if (refs)
            s += fmt::format("  {:>9} {:>9} {:>9} {:>9}", pct(errorPct(row.direct, r.sensor.refDirect)),
                             pct(errorPct(row.indirect, r.sensor.refIndirect)),
                             pct(errorPct(row.total, r.sensor.refTotal)),
                             pct(row.vertex ? errorPct(*row.vertex, r.sensor.refIndirect) : std::nullopt));
        if (factors) s += fmt::format("  {:>7}", r.daylightFactor ? fmt::format("{:.2f}", *r.daylightFactor) : "-");
        s += "\n";
    }
    return s;
}

}  // namespace rayrad::app
