// Observers: eyes in the scene where discomfort glare is reported (UGR from the
// luminaires and area lights), with the limit EN 12464-1 sets for their task.
#pragma once

#include <core/math.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::scene {

struct Observer {
    std::string name;
    std::string where;  ///< JSON pointer, for messages
    Vec3 position{0.0};           ///< the eye, m
    Vec3 direction{0, 0, -1};     ///< the line of sight, unit
    Vec3 up{0, 1, 0};             ///< unit, not parallel to the line of sight
    std::optional<double> ugrLimit;  ///< the UGR it is held to (given, or its task's)
    std::string task;                ///< the EN 12464-1 task the limit is from ("" none)
};

/// EN 12464-1's UGR limit for a kind of task, by name ("office" 19, "drawing" 16, ...;
/// ugrTaskNames lists them); nothing for a name it does not know.
std::optional<double> ugrTaskLimit(const std::string& task);
/// The task names ugrTaskLimit knows, for messages: "drawing", "office", ...
std::string ugrTaskNames();

}  // namespace rayrad::scene
