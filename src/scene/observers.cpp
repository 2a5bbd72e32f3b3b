#include <scene/observers.h>

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace rayrad::scene {

namespace {

/// EN 12464-1's UGR limits for some kinds of task (its tables give one per activity).
constexpr std::pair<const char*, double> kTaskLimits[] = {
    {"drawing", 16},      // technical drawing
    {"office", 19},       // writing, typing, reading, data processing
    {"classroom", 19},    // classrooms, tutorial rooms
    {"conference", 19},   // conference and meeting rooms
    {"reception", 22},    // reception desks
    {"industry", 22},     // medium industrial work
    {"circulation", 28},  // corridors and circulation areas
};

}  // namespace

std::optional<double> ugrTaskLimit(const std::string& task) {
    for (const auto& [name, limit] : kTaskLimits)
        if (task == name) return limit;
    return std::nullopt;
}

std::string ugrTaskNames() {
    std::string s;
    for (const auto& [name, limit] : kTaskLimits) s += fmt::format("{}\"{}\" ({:g})", s.empty() ? "" : ", ", name, limit);
    return s;
}

}  // namespace rayrad::scene
