#include <scene/sensor_names.h>

#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace rayrad::scene {

template <class S>
std::vector<size_t> sensorsNamedAgain(const std::vector<S>& sensors) {
    // A grid or work plane appends its points row by row, (v, u) rising: within such a run
    // of one grid name no two points share a cell, so no two share a name. A name with
    // two runs (two grids of one name) has its points compared.
    auto continuesRun = [&](size_t i) {
        const S &a = sensors[i - 1], &b = sensors[i];
        return a.grid == b.grid && std::make_pair(a.gridV, a.gridU) < std::make_pair(b.gridV, b.gridU);
    };
    std::unordered_map<std::string_view, int> runs;
    for (size_t i = 0; i < sensors.size(); ++i)
        if (!sensors[i].grid.empty() && (i == 0 || !continuesRun(i))) ++runs[sensors[i].grid];
    std::unordered_set<std::string_view> compared;  // grid names whose points are compared
    for (const auto& [grid, count] : runs)
        if (count > 1) compared.insert(grid);
    for (const auto& s : sensors) {
        if (!s.grid.empty()) continue;
        // A point's name is its grid's name and "[i,j]", which holds no other '['.
        const std::string_view name = s.name;
        const size_t bracket = name.rfind('[');
        if (bracket != std::string_view::npos && runs.count(name.substr(0, bracket))) compared.insert(name.substr(0, bracket));
    }
    std::vector<size_t> again;
    std::unordered_map<std::string_view, int> uses;
    for (size_t i = 0; i < sensors.size(); ++i) {
        const S& s = sensors[i];
        if ((s.grid.empty() || compared.count(s.grid)) && ++uses[s.name] == 2) again.push_back(i);
    }
    return again;
}

template std::vector<size_t> sensorsNamedAgain(const std::vector<SensorDesc>&);
template std::vector<size_t> sensorsNamedAgain(const std::vector<Sensor>&);

}  // namespace rayrad::scene
