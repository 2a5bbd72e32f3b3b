// Helpers shared by the tests: paths, Catch2 printers for our types, small scenes.
#pragma once

#include <core/math.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <string>

namespace Catch {
template <>
struct StringMaker<rayrad::Vec3> {
    static std::string convert(const rayrad::Vec3& v) { return rayrad::toString(v); }
};
}  // namespace Catch

namespace rayrad::test {

inline std::string sourcePath(const std::string& relative) { return std::string(RAYRAD_SOURCE_DIR) + "/" + relative; }

/// Writes a scene for runPipeline, which reads files: /tmp/rayrad_test_<name>.json.
inline std::string writeTempScene(const std::string& name, const std::string& json) {
    std::string path = "/tmp/rayrad_test_" + name + ".json";
    std::ofstream(path) << json;
    return path;
}

}  // namespace rayrad::test
